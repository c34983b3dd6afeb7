#version 450
// The unfolded cube map as an inset in the top-left corner of the view (INSET_WIDTH of the
// view's width, 4:3), with a thin frame; discards elsewhere.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 hdr;
uniform sampler2D unfolded;
const float kInsetWidth = 0.34, kFrame = 0.004;
void main() {
    if (!params.inset) discard;
    vec2 size = vec2(kInsetWidth, kInsetWidth * 0.75 * frame.aspect);
    vec2 q = (uv - kFrame) / size;
    if (any(greaterThan(uv, size + 2.0 * kFrame))) discard;
    hdr = any(lessThan(q, vec2(0.0))) || any(greaterThan(q, vec2(1.0))) ? vec4(0.05, 0.05, 0.05, 1.0) : vec4(texture(unfolded, q).rgb, 1.0);
}
