#version 450
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 ldr;
uniform sampler2D lit;
uniform sampler2D ao;
uniform sampler2D ao_raw;
void main() {
    vec3 c = params.show == SHOW_AO ? vec3(texture(ao, uv).r) : params.show == SHOW_RAW ? vec3(texture(ao_raw, uv).r) : texture(lit, uv).rgb;
    ldr = vec4(clamp(c, 0.0, 1.0), 1.0);
}
