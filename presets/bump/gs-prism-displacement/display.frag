#version 450
// The prisms' image, or (show = base) the undisplaced mesh, clamped to the sRGB target.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 ldr;
uniform sampler2D hdr;
uniform sampler2D base;
void main() { ldr = vec4(clamp((params.show == SHOW_BASE ? texture(base, uv) : texture(hdr, uv)).rgb, 0.0, 1.0), 1.0); }
