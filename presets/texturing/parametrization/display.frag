#version 450
// The lit object over a dark background (the scene clears to alpha 0).
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
uniform sampler2D hdr;
void main() {
    vec4 c = texture(hdr, uv);
    color = vec4(mix(vec3(0.05, 0.055, 0.07), clamp(c.rgb, 0.0, 1.0), c.a), 1.0);
}
