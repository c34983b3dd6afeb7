#version 450
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 ldr;
uniform sampler2D result;
uniform sampler2D reference;
uniform sampler2D error;
void main() {
    vec3 c = params.show == SHOW_ERROR       ? texture(error, uv).rgb * 4.0
             : params.show == SHOW_REFERENCE ? texture(reference, uv).rgb
                                             : texture(result, uv).rgb;
    ldr = vec4(clamp(c, 0.0, 1.0), 1.0);
}
