#version 450
// Face orientation round trip (the pitfall of 001_fe43b953f362fae7.txt L123-127, "addressing not
// intuitive (needs flip)"): with env = directions every texel holds the direction
// cube_face_direction gave it. Looking the cube up along that same direction must land on the
// same texel (at its centre, so the linear filter returns it unmixed): |env(d) - d| = 0 up to the
// rgba16f rounding. A face whose s or t runs the wrong way returns the mirrored texel instead.
// 6 faces x 16 x 16 texels side by side (96 x 16), for cube_size = 16.
#include "envmap/cube.glsl"
layout(location = 0) out float error;
uniform samplerCube env;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    int n = textureSize(env, 0).x;
    vec3 d = cube_face_direction(p.x / n, (vec2(p.x % n, p.y) + 0.5) / float(n));
    error = length(textureLod(env, d, 0.0).rgb - d);
}
