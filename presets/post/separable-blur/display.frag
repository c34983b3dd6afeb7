#version 450
// Left of `split`: the source; right: the separable result.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
uniform sampler2D src;
uniform sampler2D sep;

void main() {
    vec3 c = uv.x < params.split ? texture(src, uv).rgb : texture(sep, uv).rgb;
    if (abs(uv.x - params.split) < 0.002) c = vec3(1.0, 0.8, 0.1);
    color = vec4(c, 1.0);
}
