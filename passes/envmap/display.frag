#version 450
// HDR radiance to the sRGB target with a gentle shoulder (c / (1 + c/4)): the sun stays bright
// without clipping the sky.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 ldr;
uniform sampler2D hdr;
void main() { vec3 c = texture(hdr, uv).rgb; ldr = vec4(c / (1.0 + 0.25 * c), 1.0); }
