#version 450
// Gaussian: the y blur of the x blur (a round 2D kernel). Star (000_c9f7e5de708ecbb3.txt
// L3104-3106, "filter in u and v separately, add u and v texture separately"): the x blur and a
// y blur of the bright image, added, each carrying half: a cross of streaks.
#include "post/gauss17.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 bloom;
uniform sampler2D blur_h;
uniform sampler2D blur_v;
uniform sampler2D bright;
void main() {
    if (params.shape == SHAPE_GAUSSIAN) {
        bloom = texture(blur_v, uv);
    } else {
        vec4 v = gauss17_linear(bright, uv, vec2(0.0, 1.0) / vec2(textureSize(bright, 0)), false);
        bloom = 0.5 * (texture(blur_h, uv) + v);
    }
}
