#version 450
// A second pass with its own shader: edits to main.frag or tint.glsl must not rebuild it.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
layout(binding = 0) uniform sampler2D ldr;
void main() { color = vec4(texture(ldr, uv).rgb * 0.5 + 0.25, 1.0); }
