#version 450
// Two analytic height fields for tests, in the layout of bump/heightfield.frag (RGB the
// range-compressed tangent-space normal normalize(-h_u/k, -h_v/k, 1) with 1/k =
// params.bump_depth, alpha the height):
// SIMPLE_KIND 0: a ramp h = u (h_u = 1, h_v = 0): the normal is the same everywhere;
// SIMPLE_KIND 1: zero, h = 0 everywhere (the bottom of the relief);
// SIMPLE_KIND 2: a ramp h = v (h_u = 0, h_v = 1): the same along the other axis, so a test can
// see the bitangent's sign (the normal tilts towards -B; with B negated, towards +B).
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 normal_map;
#ifndef SIMPLE_KIND
#define SIMPLE_KIND 0
#endif
void main() {
#if SIMPLE_KIND == 0
    vec3 n = normalize(vec3(-params.bump_depth, 0.0, 1.0));
    normal_map = vec4(n * 0.5 + 0.5, uv.x);
#elif SIMPLE_KIND == 2
    vec3 n = normalize(vec3(0.0, -params.bump_depth, 1.0));
    normal_map = vec4(n * 0.5 + 0.5, uv.y);
#else
    normal_map = vec4(0.5, 0.5, 1.0, 0.0);
#endif
}
