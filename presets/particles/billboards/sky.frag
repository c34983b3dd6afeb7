#version 450
// A vertical gradient behind the sprites (up in world space, so the horizon tilts with pitch).
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
void main() {
    vec4 p = frame.inv_view_proj * vec4(uv * 2.0 - 1.0, 1.0, 1.0);
    vec3 d = normalize(p.xyz / p.w - frame.camera_pos.xyz);
    color = vec4(mix(vec3(0.12, 0.1, 0.09), vec3(0.25, 0.4, 0.65), smoothstep(-0.3, 0.5, d.y)), 1.0);
}
