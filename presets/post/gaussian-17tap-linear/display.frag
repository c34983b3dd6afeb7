#version 450
// Source left of the split, the 8-lookup result right of it.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 ldr;
uniform sampler2D src;
uniform sampler2D linear;
void main() {
    vec3 c = uv.x < params.split ? texture(src, uv).rgb : texture(linear, uv).rgb * 4.0;  // x4: faint dots visible
    if (abs(uv.x - params.split) < 0.0015) c = vec3(1.0, 0.8, 0.2);
    ldr = vec4(clamp(c, 0.0, 1.0), 1.0);
}
