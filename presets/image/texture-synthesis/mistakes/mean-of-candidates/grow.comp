#version 450
// One growth ring of Efros-Leung synthesis (003_cfc3b5b225ddab3d.txt L35-47, image/efros_leung.glsl).
// The paper fills one pixel at a time, always the unknown pixel with the most known neighbours
// (inherently sequential, L81-91); here every texel of a ring is filled in parallel, each from
// the rings inside it only. One thread per texel of this frame's window of the growth order
// (synth_common.glsl); the pass runs once per ring the window touches (pl_iteration), the ring
// of iteration i filling only its own texels, so inner rings are complete before outer ones
// read them. The choice is seeded per texel: a run is repeatable.
#include "synth_common.glsl"

layout(local_size_x = 8) in;
uniform sampler2D src;
layout(rgba8) uniform image2D canvas;

int g_ring;   // the ring this dispatch fills

vec4 el_canvas(ivec2 p) {
    if (any(lessThan(p, ivec2(0))) || any(greaterThanEqual(p, imageSize(canvas)))) return vec4(0.0);
    vec4 c = imageLoad(canvas, p);
    int a8 = int(round(c.a * 255.0));
    return vec4(c.rgb, (a8 >= 1 && a8 < g_ring) ? 1.0 : 0.0);
}

bool el_valid(ivec2 q) {
    int h = params.half_window;
    return all(greaterThanEqual(q, ivec2(h))) && all(lessThan(q, textureSize(src, 0) - h));
}

#include "image/efros_leung.glsl"

void main() {
    ivec2 size = imageSize(canvas);
    int first = frame.accum_frame * params.texels;
    int order = first + int(gl_GlobalInvocationID.x);
    if (int(gl_GlobalInvocationID.x) >= params.texels) return;
    g_ring = synth_ring_of(first) + pl_iteration;
    if (synth_ring_of(order) != g_ring) return;
    ivec2 p = synth_texel(order, size);
    if (any(lessThan(p, ivec2(0))) || any(greaterThanEqual(p, size))) return;
    el_gather(p, params.half_window);
    ivec2 q = el_choose(src, params.epsilon, uvec3(p, uint(params.seed) * 65537u));
    imageStore(canvas, p, vec4(el_mean,   // the mean of the candidates, smoother
                                  float(g_ring) / 255.0));
}
