#version 450
// Mean TAA error over mean single-frame error (the 1x1 mips of the two error images).
layout(location = 0) out float ratio;
uniform sampler2D err_taa;
uniform sampler2D err_cur;
void main() { ratio = textureLod(err_taa, vec2(0.5), 16.0).r / max(textureLod(err_cur, vec2(0.5), 16.0).r, 1e-9); }
