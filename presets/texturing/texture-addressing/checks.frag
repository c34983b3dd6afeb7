#version 450
// Each output texel holds a difference that the addressing rules make exactly zero
// (000_c9f7e5de708ecbb3.txt L1593-1616), the border colour, and the sRGB decode.
layout(location = 0) out vec4 color;
uniform sampler2D repeat_nearest;
uniform sampler2D mirror_nearest;
uniform sampler2D clamp_nearest;
uniform sampler2D border_nearest;
uniform sampler2D srgb_texel;

void main() {
    int x = int(gl_FragCoord.x);
    const float v = 0.375;  // a texel-centre row
    if (x == 0) color = vec4(texture(repeat_nearest, vec2(0.3, v)).rgb - texture(repeat_nearest, vec2(1.3, v)).rgb, 1.0);
    else if (x == 1) color = vec4(texture(mirror_nearest, vec2(1.3, v)).rgb - texture(mirror_nearest, vec2(0.7, v)).rgb, 1.0);
    else if (x == 2) color = vec4(texture(clamp_nearest, vec2(1.6, v)).rgb - texture(clamp_nearest, vec2(0.99, v)).rgb, 1.0);
    else if (x == 3) color = texture(border_nearest, vec2(1.5, v));
    else if (x == 4) color = texture(srgb_texel, vec2(0.5));
    else color = vec4(texture(repeat_nearest, vec2(0.3, v)).r != texture(repeat_nearest, vec2(0.7, v)).r ? 1.0 : 0.0);
}
