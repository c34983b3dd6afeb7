#version 450
// A mirror object: R = V - 2 (N.V) N in world space (001_fe43b953f362fae7.txt L251-260), looked
// up in both paraboloid maps (lookup.glsl). View independent: the maps are baked once.
#include "lookup.glsl"
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 0) out vec4 hdr;
void main() {
    vec3 n = normalize(v_normal), V = normalize(v_world - frame.camera_pos.xyz);
    hdr = vec4(params.tint * environment(V - 2.0 * dot(n, V) * n), 1.0);
}
