#version 450
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 ldr;
uniform sampler2D taa;
uniform sampler2D cur;
uniform sampler2D err_taa;
void main() {
    vec3 c = params.show == SHOW_CURRENT ? texture(cur, uv).rgb : params.show == SHOW_ERROR ? vec3(texture(err_taa, uv).r * 4.0) : texture(taa, uv).rgb;
    ldr = vec4(clamp(c, 0.0, 1.0), 1.0);
}
