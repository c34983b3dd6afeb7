#version 450
// Exposure and Hejl tone mapping (passes/post/tonemap.glsl; display-encoded, to a UNORM
// target); or the CoC (red: near, blue: far, full at params.taps pixels); or, split, the sharp
// image on the left.
#include "post/tonemap.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 ldr;
uniform sampler2D src;
uniform sampler2D blurred;
uniform sampler2D result;
void main() {
    // zoom > 1 magnifies the centre (nearest: texels stay squares), e.g. the point scene's kernel.
    ivec2 t = ivec2(floor((0.5 + (uv - 0.5) / params.zoom) * frame.resolution.xy));
    ivec2 tb = params.resolution == RESOLUTION_HALF ? min(t / 2, textureSize(blurred, 0) - 1) : t;  // blurred is view/2 at half resolution (odd sizes: clamp)
    vec3 c = params.show == SHOW_BLUR ? texelFetch(blurred, tb, 0).rgb : texelFetch(result, t, 0).rgb;
    if (params.show == SHOW_SHARP || (params.split && uv.x < 0.5)) c = texelFetch(src, t, 0).rgb;
    // The point scene's texel holds w x h: scale so a hexagon of circumradius R = point_coc
    // (area 3 sqrt(3) / 2 R^2) shows about 1.
    if (params.scene == SCENE_POINT) c *= 2.598 * params.point_coc * params.point_coc / (frame.resolution.x * frame.resolution.y);
    c = tonemap_hejl(c * params.exposure);
    if (params.show == SHOW_COC) {
        float k = texelFetch(src, t, 0).w * frame.resolution.y / (float(params.taps) * (params.resolution == RESOLUTION_HALF ? 2.0 : 1.0));
        c = vec3(max(-k, 0.0), 0.0, max(k, 0.0));
    }
    if (params.split && abs(uv.x - 0.5) < 0.0015) c = vec3(1.0, 0.8, 0.2);
    ldr = vec4(clamp(c, 0.0, 1.0), 1.0);
}
