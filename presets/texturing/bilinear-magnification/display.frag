#version 450
// Three bands of the same magnification: nearest | hardware LINEAR | shader bilinear.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 ldr;
uniform sampler2D pattern;
uniform sampler2D ramp;
uniform sampler2D hw;
uniform sampler2D sw;
void main() {
    int band = params.split ? int(uv.x * 3.0) : 1;
    vec2 t = params.split ? vec2(fract(uv.x * 3.0), uv.y) : uv;
    vec3 c = band == 0 ? (params.source == SOURCE_RAMP2X2 ? texture(ramp, t).rgb : texture(pattern, t).rgb)
             : band == 1 ? texture(hw, uv).rgb
                         : texture(sw, uv).rgb;
    if (params.split && (abs(uv.x - 1.0 / 3.0) < 0.0015 || abs(uv.x - 2.0 / 3.0) < 0.0015)) c = vec3(1.0, 0.8, 0.2);
    ldr = vec4(c, 1.0);
}
