#version 450
// The counts are 1/255 everywhere, invisible as they are: show count * 255 / 2 (mid gray for
// one fragment, white for two, black for none), triangle on the left, quad on the right.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
uniform sampler2D by_triangle;
uniform sampler2D by_quad;
void main() {
    float n = (uv.x < 0.5 ? texture(by_triangle, uv).r : texture(by_quad, uv).r) * 255.0;
    color = vec4(vec3(n * 0.5) * vec3(uv.x < 0.5 ? 1.0 : 0.8, 1.0, uv.x < 0.5 ? 0.8 : 1.0), 1.0);
}
