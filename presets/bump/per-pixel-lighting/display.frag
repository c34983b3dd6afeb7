#version 450
// Left half the 16-segment sphere, right half the 256-segment one (each at its own place).
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 ldr;
uniform sampler2D coarse;
uniform sampler2D fine;
void main() {
    // Each half shows its sphere centred: sample the full image around its centre.
    vec2 q = vec2(fract(uv.x * 2.0) * 0.5 + 0.25, uv.y);
    vec3 c = uv.x < 0.5 ? texture(coarse, q).rgb : texture(fine, q).rgb;
    if (abs(uv.x - 0.5) < 0.0015) c = vec3(1.0, 0.8, 0.2);
    ldr = vec4(clamp(c, 0.0, 1.0), 1.0);
}
