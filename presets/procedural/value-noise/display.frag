#version 450
// n in [-1, 1] shown as gray g = (n + 1) / 2. The target is sRGB, so g is decoded first: the
// stored (and displayed) value is then g itself, and mid-gray means n = 0.
#include "common/color.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
uniform sampler2D noise;
void main() {
    float g = 0.5 * texture(noise, uv).r + 0.5;
    color = vec4(srgb_to_linear(vec3(g)), 1.0);
}
