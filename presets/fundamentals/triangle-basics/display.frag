#version 450
// Left: the interpolated triangle. Right: the shared-edge quad (0.5 everywhere it is drawn).
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
uniform sampler2D rgb;
uniform sampler2D edge;
void main() {
    color = uv.x < 0.5 ? vec4(texture(rgb, vec2(uv.x * 2.0, uv.y)).rgb, 1.0)
                       : vec4(texture(edge, vec2(uv.x * 2.0 - 1.0, uv.y)).rrr, 1.0);
}
