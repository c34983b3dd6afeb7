#version 450
// EXERCISE — light volumes, the shading (003_cfc3b5b225ddab3d.txt L886-888: the rasteriser
// evaluates the "light-fragment interaction predicate", not the shader). TODO 3 here; TODO 1
// and 2 are in volume.vert.
// This fragment is a pixel covered by light v_light's volume. The pass blends additively
// (preset.toml: blend = "additive", out = src + dst) into `lit`, which the ambient pass filled
// with the ambient term of every pixel first; each volume adds its own light on top.
// COUNT (pass volumes_counted: tests and show = count) also counts the shaded light-pixel pairs
// and the lights per pixel; leave it as it is.
#include "deferred/lights.glsl"
layout(location = 0) flat in int v_light;
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
    // TODO 3: the G-buffer sample at px: world position (position.xyz), unit normal (normal.xyz,
    // renormalise: fp16 storage), the direction to the eye (frame.camera_pos), the material
    // (albedo rgb, specular intensity in mat.a). Write what light v_light alone adds here:
    // shade_point_light(point_light(v_light, frame.time), p, n, v, albedo, specular, kShininess)
    // (passes/deferred/lights.glsl). Whatever you write is added to lit: what else, if
    // anything, belongs in it? (The alpha channel is not displayed.)
    lit = vec4(0.0);
}
