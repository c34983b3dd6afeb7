#version 450
// Display: the shaded image, tinted by the cascade each pixel used when show_cascades is on
// (0 red, 1 green, 2 blue, 3 yellow; the blend bands mix the two tints by their weight).
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
uniform sampler2D ldr;
uniform sampler2D cascade_info;
void main() {
    const vec3 tint[5] = vec3[](vec3(1.0, 0.55, 0.55), vec3(0.55, 1.0, 0.55), vec3(0.55, 0.65, 1.0), vec3(1.0, 1.0, 0.5), vec3(1.0));
    vec4 info = texture(cascade_info, uv);
    vec3 c = texture(ldr, uv).rgb;
    int i = int(info.r + 0.5);
    if (params.show_cascades && info.r >= 0.0)
        c *= mix(tint[min(i, 3)], tint[min(i + 1, 4)], info.b);
    color = vec4(c, 1.0);
}
