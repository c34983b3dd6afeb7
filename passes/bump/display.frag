#version 450
// Linear radiance, clamped, to the sRGB target (the bump presets light in [0, 1] anyway).
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 ldr;
uniform sampler2D hdr;
void main() { ldr = vec4(clamp(texture(hdr, uv).rgb, 0.0, 1.0), 1.0); }
