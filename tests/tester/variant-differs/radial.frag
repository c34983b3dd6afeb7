#version 450
// gain * (1 - r)^2 for r = distance to the centre in uv units (a radially symmetric bump).
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
void main() {
    float r = min(length(uv - 0.5) * 2.0, 1.0);
    float v = params.gain * (1.0 - r) * (1.0 - r);
    color = vec4(v, v * 0.5, 1.0 - r, 1.0);
}
