#version 450
// Four panels of the same texture region (2 x 2): source (rgba8, 4 bytes per texel) | hardware
// BC1 decode | shader BC1 decode of the same blocks | a diagnostic (params.fourth):
//   error:   |hardware - source| x params.error_gain (alpha errors white)
//   indices: the 2-bit index per texel as grey 0, 1/3, 2/3, 1 (red: index 3 = transparent)
//   modes:   blue blocks four-colour (color0 > color1), orange three-colour + transparent
//            (color0 < color1), grey one colour (color0 == color1: also three-colour mode by
//            the rule, but every index the encoder uses gives color0)
// Transparent texels show a grey checkerboard behind them. params.zoom magnifies around
// params.centre (nearest: one texel = zoom x zoom pixels), params.grid outlines the 4x4 blocks.
#include "texturing/bc1.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 ldr;
uniform sampler2D src;
uniform sampler2D hw;
uniform sampler2D sw;
uniform sampler2D err;
layout(std430) readonly buffer Blocks { uvec2 words[]; } blocks;

const vec3 kFrame = vec3(0.08);           // outside the texture, and the panel separators
const vec3 kFourColour = vec3(0.20, 0.45, 0.95);
const vec3 kThreeColour = vec3(1.00, 0.55, 0.10);
const vec3 kOneColour = vec3(0.55);

vec3 over_checker(vec4 c) {
    vec2 cell = floor(gl_FragCoord.xy / 8.0);
    vec3 back = mod(cell.x + cell.y, 2.0) < 1.0 ? vec3(0.30) : vec3(0.55);
    return mix(back, c.rgb, c.a);
}

void main() {
    vec2 panels = vec2(2.0);
    ivec2 panel = ivec2(min(uv * panels, panels - 1.0));
    vec2 local = fract(uv * panels);
    vec2 px = frame.resolution.xy / panels;   // one panel's size in pixels
    ivec2 size = textureSize(src, 0);
    // Keep texels square: the panel's shorter side spans 1 / zoom of the texture.
    vec2 span = vec2(px / min(px.x, px.y)) / params.zoom;
    vec2 tc = params.centre + (local - 0.5) * span;
    vec3 c = kFrame;
    if (all(greaterThanEqual(tc, vec2(0.0))) && all(lessThan(tc, vec2(1.0)))) {
        ivec2 t = ivec2(tc * vec2(size));
        int which = panel.y * 2 + panel.x;
        if (which == 0) c = over_checker(texelFetch(src, t, 0));
        else if (which == 1) c = over_checker(texelFetch(hw, t, 0));
        else if (which == 2) c = over_checker(texelFetch(sw, t, 0));
        else {
            uvec2 block = blocks.words[bc1_block_of(t, size.x)];
            if (params.fourth == FOURTH_ERROR) {
                c = clamp(texelFetch(err, t, 0).rgb * params.error_gain, 0.0, 1.0);
            } else if (params.fourth == FOURTH_INDICES) {
                uint i = bc1_index(block, bc1_in_block(t));
                c = (i == 3u && bc1_three_colour(block)) ? vec3(0.9, 0.1, 0.1) : vec3(float(i) / 3.0);
            } else {
                uint c0 = block.x & 0xFFFFu, c1 = block.x >> 16;
                c = c0 > c1 ? kFourColour : (c0 < c1 ? kThreeColour : kOneColour);
            }
        }
        // Block outlines: one pixel at each block edge, when a texel is at least 4 pixels.
        vec2 texel_px = px / (span * vec2(size));
        vec2 in_block = tc * vec2(size) / float(kBc1BlockSide);
        vec2 edge = fract(in_block) * float(kBc1BlockSide) * texel_px;   // pixels past the edge
        if (params.grid && min(texel_px.x, texel_px.y) >= 4.0 && (edge.x < 1.0 || edge.y < 1.0)) c = mix(c, vec3(1.0), 0.35);
    }
    // Separators between the panels.
    vec2 sep = abs(uv - 0.5) * frame.resolution.xy;
    if (min(sep.x, sep.y) < 1.0) c = kFrame;
    ldr = vec4(c, 1.0);
}
