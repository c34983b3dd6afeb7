#version 450
// The flat copy darkens what is under it (000 L4492 "darken surface underneath using framebuffer
// blend"): alpha = params.opacity with blend dst * (1 - alpha) (src_color = zero, dst_color =
// one_minus_src_alpha), into the colour and the visibility target alike, so `vis` reads
// 1 - opacity where one copy landed and (1 - opacity)^2 where two did (double blending).
layout(location = 0) out vec4 color;
layout(location = 1) out vec4 vis;
void main() {
    color = vec4(0.0, 0.0, 0.0, params.opacity);
    vis = vec4(0.0, 0.0, 0.0, params.opacity);
}
