#version 450
// An image shown as an inset in the top-left corner of the view, with a thin dark frame
// (discards elsewhere; draw it after the scene into the same target). Defines:
//   INSET_ON     expression, the inset is drawn when true (default true)
//   INSET_WIDTH  fraction of the view's width (default 0.3)
//   INSET_ASPECT the inset's width / height (default 1)
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 hdr;
uniform sampler2D inset_src;
#ifndef INSET_ON
#define INSET_ON true
#endif
#ifndef INSET_WIDTH
#define INSET_WIDTH 0.3
#endif
#ifndef INSET_ASPECT
#define INSET_ASPECT 1.0
#endif
const float kFrame = 0.004;  // frame width, fraction of the view's width
void main() {
    if (!(INSET_ON)) discard;
    vec2 frame_uv = vec2(kFrame, kFrame * frame.aspect);
    vec2 size = vec2(INSET_WIDTH, INSET_WIDTH / INSET_ASPECT * frame.aspect);
    if (any(greaterThan(uv, size + 2.0 * frame_uv))) discard;
    vec2 q = (uv - frame_uv) / size;
    hdr = any(lessThan(q, vec2(0.0))) || any(greaterThan(q, vec2(1.0))) ? vec4(0.05, 0.05, 0.05, 1.0) : vec4(texture(inset_src, q).rgb, 1.0);
}
