#version 450
// EXERCISE — light volumes (003_cfc3b5b225ddab3d.txt L886-887: "rasterize geometry of light
// volume (only generate fragments for covered G-buffer samples)"). Fill in TODO 1 and 2 here
// and TODO 3 in volume.frag, then check your work against the reference:
//     passlab run   deferred/light-volumes --exercise presets/deferred/light-volumes/exercise
//     passlab grade deferred/light-volumes --exercise presets/deferred/light-volumes/exercise
// One instance per light (gl_InstanceIndex = i): the mesh `volume` is a 16 x 8 UV sphere of
// radius 1 around the origin, and this shader must turn it into light i's volume, a closed
// shape around every point the light reaches. point_light(i, frame.time)
// (passes/deferred/lights.glsl) gives its centre l.position and its radius l.radius, past
// which its falloff is exactly 0. The pass (preset.toml) draws the volume's back faces with
// the depth test greater_equal: a pixel is shaded for the light where the scene surface lies
// in front of the volume's far side.
#include "deferred/lights.glsl"
layout(location = 0) in vec3 position;
layout(location = 0) flat out int v_light;
// TODO 2: the mesh is a polygon inscribed in the unit sphere: its vertices lie on the sphere,
// its flat triangles inside it (the ones next to the equator at 0.963 of the radius). Scaled
// by the light's radius alone it misses the edge of the light's sphere. By what factor must
// it grow so that it contains the whole sphere?
const float kCover = 1.0;
void main() {
    PointLight l = point_light(gl_InstanceIndex, frame.time);
    v_light = gl_InstanceIndex;
    // TODO 1: the world position of this vertex of light l's volume: the unit sphere scaled to
    // the light's reach (times kCover) and moved to the light.
    vec3 world = position;
    gl_Position = frame.view_proj * vec4(world, 1.0);
    // Instances past params.lights draw nothing (a point outside the clip volume).
    if (gl_InstanceIndex >= params.lights) gl_Position = vec4(0.0, 0.0, -2.0, 1.0);
}
