#version 450
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 ldr;
uniform sampler2D deferred;
uniform sampler2D forward;
uniform sampler2D packed;
uniform sampler2D albedo;
uniform sampler2D normal;
uniform sampler2D position;
void main() {
    vec3 c = params.show == SHOW_FORWARD      ? texture(forward, uv).rgb
             : params.show == SHOW_PACKED     ? texture(packed, uv).rgb
             : params.show == SHOW_ALBEDO     ? texture(albedo, uv).rgb
             : params.show == SHOW_NORMAL     ? texture(normal, uv).xyz * 0.5 + 0.5
             : params.show == SHOW_POSITION   ? fract(texture(position, uv).xyz)
             : params.show == SHOW_DIFFERENCE ? abs(texture(deferred, uv).rgb - texture(forward, uv).rgb) * 50.0
                                              : texture(deferred, uv).rgb;
    ldr = vec4(clamp(c, 0.0, 1.0), 1.0);
}
