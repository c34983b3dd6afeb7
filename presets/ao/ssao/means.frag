#version 450
// The two images' means (their 1x1 mips) and their ratio, for the blur test: x = raw / blurred.
layout(location = 0) out vec2 means;
uniform sampler2D ao_raw;
uniform sampler2D ao;
void main() {
    float raw = textureLod(ao_raw, vec2(0.5), 16.0).r, blurred = textureLod(ao, vec2(0.5), 16.0).r;
    means = vec2(raw / max(blurred, 1e-6), blurred);
}
