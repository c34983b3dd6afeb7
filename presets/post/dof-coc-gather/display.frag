#version 450
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 ldr;
uniform sampler2D result;
uniform sampler2D result_half;
uniform sampler2D color;
uniform sampler2D coc;
// resolution = half: the half-res gather upsampled (bilinear) where the blur radius r (pixels) is
// 2 px or more, the sharp input where it is 1 px or less (the 2x2 grid would soften an in-focus
// surface), linear between:  out = mix(sharp, gathered, clamp(r - 1, 0, 1)).
vec3 composite_half() {
    float r = abs(texelFetch(coc, ivec2(gl_FragCoord.xy), 0).x) * frame.resolution.y;
    return mix(texelFetch(color, ivec2(gl_FragCoord.xy), 0).rgb, texture(result_half, uv).rgb, clamp(r - 1.0, 0.0, 1.0));
}
void main() {
    float c = texture(coc, uv).x * frame.resolution.y / 24.0;
    vec3 v = params.show == SHOW_COC ? vec3(max(-c, 0.0), 0.0, max(c, 0.0))
             : params.resolution == RESOLUTION_HALF ? composite_half() : texture(result, uv).rgb;
    ldr = vec4(clamp(v, 0.0, 1.0), 1.0);
}
