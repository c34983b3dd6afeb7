#version 450
// Dual depth peeling, per pass: the front layer goes under the front accumulator (front to back,
// blend { one_minus_dst_alpha, one }) and the back layer over the back accumulator (back to front,
// premultiplied over: blend { one, one_minus_src_alpha }), which started as the opaque colour.
// The final image is the front accumulator over the back one (oit/under_resolve.frag).
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 front_acc;
layout(location = 1) out vec4 back_acc;
uniform sampler2D front_layer;
uniform sampler2D back_layer;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    front_acc = texelFetch(front_layer, p, 0);
    back_acc = texelFetch(back_layer, p, 0);
}
