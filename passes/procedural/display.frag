#version 450
// Display of the procedural presets: an rgba16f image (bound as hdr), clamped to [0, 1] into the sRGB target.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
uniform sampler2D hdr;
void main() { color = vec4(clamp(texture(hdr, uv).rgb, 0.0, 1.0), 1.0); }
