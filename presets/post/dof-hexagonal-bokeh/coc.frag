#version 450
// 002's layout for the hexagonal blur (002_644d46bdce7e5305.txt L1318-1336): colour in rgb,
// the circle of confusion in alpha, negative = near field (in front of the focus), as a fraction of
// the image height (002 L1254-1287, passes/post/coc.glsl).
// scene = point: a black image with one texel of radiance w x h at the centre (mean 1) and one
// CoC everywhere, params.point_coc pixels: the kernel itself (tests).
#include "post/coc.glsl"
layout(location = 0) out vec4 src;
uniform sampler2D color;
uniform sampler2D depth;
const float kNear = 0.1, kFar = 100.0;  // passes/post/bokeh_scene.frag's clip planes
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy), size = ivec2(frame.resolution.xy);
    if (params.scene == SCENE_POINT) {
        float v = p == size / 2 ? float(size.x * size.y) : 0.0;
        src = vec4(vec3(v), params.point_coc / frame.resolution.y);
        return;
    }
    float d = texelFetch(depth, p, 0).y;
    src = vec4(texelFetch(color, p, 0).rgb, coc_linear_in_depth(d, params.focus, params.fov_factor, params.diameter, kNear, kFar));
}
