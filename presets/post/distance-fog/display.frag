#version 450
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 ldr;
uniform sampler2D fogged;
uniform sampler2D factor;
uniform sampler2D depth;
void main() {
    vec3 c = params.show == SHOW_FACTOR     ? vec3(texture(factor, uv).r)
             : params.show == SHOW_DISTANCE ? vec3(1.0 - texture(depth, uv).r) * 20.0
                                            : texture(fogged, uv).rgb;
    ldr = vec4(clamp(c, 0.0, 1.0), 1.0);
}
