#version 450
// The deferred presets' scene: FLOOR draws the ground plane, otherwise the mesh is instanced
// over a jittered 8 x 8 grid (hash-placed sizes, passes/deferred/objects.glsl). World position,
// normal, and a per-object material (albedo, specular) to the fragment shader. CROWD (optional):
// the instances are the moving crowd of scene_ball_crowd instead (up to kCrowdBalls). VISIBLE (an
// expression, optional) hides the draw when false: every vertex outside the clip volume.
#include "deferred/objects.glsl"
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 v_world;
layout(location = 1) out vec3 v_normal;
layout(location = 2) flat out vec4 v_material;  // rgb albedo, a specular intensity

void main() {
#ifdef FLOOR
    vec3 p = position, n = normal;
    v_material = kFloorMaterial;
#else
#ifdef CROWD
    SceneBall b = scene_ball_crowd(gl_InstanceIndex, frame.time);
#else
    SceneBall b = scene_ball(gl_InstanceIndex);
#endif
    vec3 p = position * b.scale + b.centre;
    vec3 n = normal;
    v_material = b.material;
#endif
    v_world = p;
    v_normal = n;
    gl_Position = frame.view_proj * vec4(p, 1.0);
#ifdef VISIBLE
    if (!(VISIBLE)) gl_Position = vec4(0.0, 0.0, -2.0, 1.0);
#endif
}
