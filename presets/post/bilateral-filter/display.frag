#version 450
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 ldr;
uniform sampler2D color;
uniform sampler2D filtered;
void main() {
    vec3 c = params.split && uv.x < 0.5 ? texture(color, uv).rgb : texture(filtered, uv).rgb;
    if (params.split && abs(uv.x - 0.5) < 0.0015) c = vec3(1.0, 0.8, 0.2);
    ldr = vec4(clamp(c, 0.0, 1.0), 1.0);
}
