#version 450
// A mirror object: R = V - 2 (N.V) N in world space (001_fe43b953f362fae7.txt L251-260), looked
// up in both paraboloid maps (lookup.glsl). View independent: the maps are baked once.
#include "lookup.glsl"
#include "envmap/reflect.glsl"
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 0) out vec4 hdr;
void main() {
    hdr = vec4(params.tint * environment(view_reflection(v_world, v_normal)), 1.0);
}
