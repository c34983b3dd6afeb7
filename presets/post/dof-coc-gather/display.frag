#version 450
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 ldr;
uniform sampler2D result;
uniform sampler2D coc;
void main() {
    float c = texture(coc, uv).x * frame.resolution.y / 24.0;
    vec3 v = params.show == SHOW_COC ? vec3(max(-c, 0.0), 0.0, max(c, 0.0)) : texture(result, uv).rgb;
    ldr = vec4(clamp(v, 0.0, 1.0), 1.0);
}
