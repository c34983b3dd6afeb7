#version 450
// The mirror ball at the cube map's centre: R = V - 2 (N.V) N (001_fe43b953f362fae7.txt
// L251-260) looked up in this frame's cube map. The ball itself is not in the cube map (it would
// hide everything from its own centre). The lookup ignores where on the ball R starts: exact at
// the centre, a parallax error of up to the ball's radius for the nearby boxes.
#include "envmap/reflect.glsl"
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 0) out vec4 hdr;
uniform samplerCube env;
void main() {
    hdr = vec4(params.tint * texture(env, view_reflection(v_world, v_normal)).rgb, 1.0);
}
