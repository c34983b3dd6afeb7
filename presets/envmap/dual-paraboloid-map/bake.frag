#version 450
// The two paraboloid maps, warped from a cube map (001_fe43b953f362fae7.txt L233-235: "can only
// be generated using ray tracing or warping"), one layer per pass iteration (repeat = 2,
// layer = "iteration"): layer 0 the +z map, layer 1 the -z map. A texel at (s, t) inside the
// unit disc holds the environment in direction r = (2 s, 2 t, +-(1 - rho^2)) / (1 + rho^2) with
// alpha 1; outside the disc (0, 0, 0, 0): premultiplied, as dp_lookup expects.
#include "envmap/dual_paraboloid.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 map;
uniform samplerCube env;
void main() {
    vec2 st = dp_st(uv);
    map = dot(st, st) <= 1.0 ? vec4(textureLod(env, dp_direction(st, pl_iteration), 0.0).rgb, 1.0) : vec4(0.0);
}
