#version 450
// First frame (frame.accum_frame == 0): the canvas is the known picture, each known texel with
// a8 = 1 (layer 0), the hole unknown (a8 = 0). Later frames leave it as the fill left it.
layout(local_size_x = 8, local_size_y = 8) in;
uniform sampler2D known;
layout(rgba8) uniform writeonly image2D canvas;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (frame.accum_frame > 0 || any(greaterThanEqual(p, imageSize(canvas)))) return;
    vec4 c = texelFetch(known, p, 0);
    imageStore(canvas, p, c.a > 0.0 ? vec4(c.rgb, 1.0 / 255.0) : vec4(0.0));
}
