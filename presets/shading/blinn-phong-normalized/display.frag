#version 450
// Linear radiance to the sRGB output; a simple Reinhard curve keeps bright highlights readable.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
uniform sampler2D hdr;
void main() {
    vec3 c = texture(hdr, uv).rgb;
    color = vec4(c / (1.0 + c), 1.0);
}
