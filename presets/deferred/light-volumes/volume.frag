#version 450
// Light volumes (003_cfc3b5b225ddab3d.txt L879-905, "rasterize geometry of light volume: only
// generate fragments for covered G-buffer samples"): the rasteriser and the depth test decide
// which pixels a light may touch; the shader lights them with that one light, added by blending.
// COUNT (pass volumes_counted: tests and show = count) also counts the shaded light-pixel pairs
// and the lights per pixel. The counters' atomics are side effects, so the driver runs the
// shader before the depth test (late tests) for every fragment of the volume: the counted
// pass costs ~3x the plain one on lavapipe, where the depth test rejects fragments first.
#include "deferred/lights.glsl"
layout(location = 0) flat in int v_light;
layout(location = 1) flat in vec4 v_sphere;  // point_light(v_light, frame.time), from volume.vert
layout(location = 2) flat in vec3 v_color;
layout(location = 0) out vec4 lit;
uniform sampler2D albedo;
uniform sampler2D normal;
uniform sampler2D position;
#ifdef COUNT
layout(std430) buffer shaded { uint samples; };
layout(r32ui) uniform uimage2D count;
#endif
const float kShininess = 32.0;
void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec4 nw = texelFetch(normal, px, 0);
    if (nw.w == 0.0) discard;
#ifdef COUNT
    atomicAdd(samples, 1u);
    imageAtomicAdd(count, px, 1u);
#endif
    vec4 mat = texelFetch(albedo, px, 0);
    vec3 p = texelFetch(position, px, 0).xyz, n = normalize(nw.xyz), v = normalize(frame.camera_pos.xyz - p);
    PointLight l = PointLight(v_sphere.xyz, v_color, v_sphere.w);  // = point_light(v_light, frame.time)
    lit = vec4(shade_point_light(l, p, n, v, mat.rgb, mat.a, kShininess), 0.0);
}
