#version 450
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 ldr;
uniform sampler2D field;
void main() {
    vec4 f = texture(field, uv);
    vec3 c = vec3(clamp(f.w, 0.0, 1.0));
    if (params.show_points && f.x < 0.04) c = vec3(1.0, 0.3, 0.1);
    ldr = vec4(c, 1.0);
}
