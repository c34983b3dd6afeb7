#version 450
// Ten cells left to right: off, nothing, alpha, additive, saturate, subtract, reverse_subtract, min, max, multiply.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
uniform sampler2D off;
uniform sampler2D nothing;
uniform sampler2D alpha;
uniform sampler2D additive;
uniform sampler2D saturate;
uniform sampler2D subtract;
uniform sampler2D reverse_subtract;
uniform sampler2D min;
uniform sampler2D max;
uniform sampler2D multiply;
void main() {
    int cell = int(uv.x * 10.0);
    vec2 c_uv = vec2(fract(uv.x * 10.0), uv.y);
    vec4 c = vec4(0);
    if (cell == 0) c = texture(off, c_uv);
    if (cell == 1) c = texture(nothing, c_uv);
    if (cell == 2) c = texture(alpha, c_uv);
    if (cell == 3) c = texture(additive, c_uv);
    if (cell == 4) c = texture(saturate, c_uv);
    if (cell == 5) c = texture(subtract, c_uv);
    if (cell == 6) c = texture(reverse_subtract, c_uv);
    if (cell == 7) c = texture(min, c_uv);
    if (cell == 8) c = texture(max, c_uv);
    if (cell == 9) c = texture(multiply, c_uv);
    bool edge = fract(uv.x * 10.0) < 0.03;
    // Values are stored as written (UNORM): decode so the display shows them as numbers, not light.
    color = edge ? vec4(0, 0, 0, 1) : vec4(pow(c.rgb, vec3(2.2)), 1.0);
}
