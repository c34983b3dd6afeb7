#version 450
// The monoliths (instances of a unit cube, GROUND undefined) or the ground plane (GROUND = 1),
// through the pass's camera, with the sunlight that reaches each vertex: the sun's for the shadow map, the view's for shading. Instances past
// params.objects (or the ground with params.ground off) collapse to a point: no fragments.
#include "volumetric/monoliths.glsl"
#include "volumetric/atmosphere.glsl"
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 v_world;
layout(location = 1) out vec3 v_normal;
layout(location = 2) out vec3 v_sun_transmittance;
void main() {
#ifdef GROUND
    mat4 model = ground_model();
    bool visible = params.ground;
#else
    mat4 model = monolith_model(gl_InstanceIndex);
    bool visible = gl_InstanceIndex < params.objects;
#endif
    v_world = (model * vec4(position, 1.0)).xyz;
    v_normal = normalize(mat3(model) * normal);   // axis-aligned scales: the normal keeps its axis
    // Sunlight reaching the vertex through the atmosphere (16-sample march to the sun): per vertex,
    // since it varies slowly over the scene (with height, and barely over 30 km of ground).
    vec3 sun = atmo_sun_direction(params.sun_elevation, params.sun_azimuth);
    v_sun_transmittance = atmo_transmittance(atmo_sun_depth(v_world + vec3(0.0, ATMO_RE, 0.0), sun, 16));
    gl_Position = visible ? frame.view_proj * vec4(v_world, 1.0) : vec4(0.0, 0.0, 2.0, 1.0);
}
