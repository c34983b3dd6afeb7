#version 450
// Row 0: the projected light along the projector's central ray, at distances 0.5, 1, 2, 4, 8,
// 16 in front (x = 0..5), as a fraction of intensity on a surface facing the projector; it
// must be the slide's centre texture(slide, (0.5, 0.5)), which x = 6 and 7 hold for reference.
// Row 1: points behind the projector (mirror images of in-frustum points): must be 0.
#include "projector.glsl"
layout(location = 0) out vec4 result;
uniform sampler2D slide_uv_grid;
const float kDist[6] = float[](0.5, 1.0, 2.0, 4.0, 8.0, 16.0);
void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec3 eye = params.proj_pos, fwd = normalize(params.proj_target - eye);
    vec3 side = normalize(cross(fwd, vec3(0.0, 1.0, 0.0))), up = cross(side, fwd);
    if (px.x >= 6) { result = vec4(textureLod(slide_uv_grid, vec2(0.5), 0.0).rgb, 1.0); return; }
    float k = kDist[px.x];
    vec3 p;
    if (px.y == 0) p = eye + k * fwd;
    else p = eye - k * fwd + 0.1 * k * (float(px.x & 1) * side + float((px.x >> 1) & 1) * up);
    // a surface facing the projector: n = l, so the cosine is 1
    vec3 light = projector_light(slide_uv_grid, p, normalize(eye - p)) / params.intensity;
    result = vec4(light, 1.0);
}
