#version 450
// Pass 2 uses pass 1's attachments as textures (000 L2020-2024: "color attachment is bound as
// texture"), lit a little so the boxes read as boxes.
layout(location = 0) in vec2 v_uv;
layout(location = 1) in vec3 v_normal;
layout(location = 2) flat in int v_which;
layout(location = 0) out vec4 hdr;
uniform sampler2D rt_color;
uniform sampler2D rt_normal;
void main() {
    vec3 t = v_which == 0 ? texture(rt_color, v_uv).rgb : texture(rt_normal, v_uv).rgb;
    float shade = 0.55 + 0.45 * max(dot(normalize(v_normal), normalize(vec3(0.3, 0.8, 0.6))), 0.0);
    hdr = vec4(t * shade, 1.0);
}
