#version 450
// value: gray (n + 1)/2. slope: |dn/dx| from neighbouring pixels, where the cubic fade's
// discontinuous second derivative shows as creases along the cell borders.
#include "common/color.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
uniform sampler2D noise;
void main() {
    float g;
    if (params.shade == SHADE_VALUE) {
        g = 0.5 * texture(noise, uv).r + 0.5;
    } else {
        // Central difference over two pixels, in noise units per lattice cell.
        vec2 texel = 1.0 / vec2(textureSize(noise, 0));
        float dx = texture(noise, uv + vec2(texel.x, 0)).r - texture(noise, uv - vec2(texel.x, 0)).r;
        float cells_per_pixel = params.cells / frame.resolution.y;
        g = clamp(0.5 * abs(dx) / (2.0 * cells_per_pixel), 0.0, 1.0);
    }
    color = vec4(srgb_to_linear(vec3(g)), 1.0);
}
