#version 450
// Shading with the tile's list: the same Lambert + Blinn-Phong per light as the fullscreen loop
// (passes/deferred/lights.glsl), over the tile's lights only. `missing` counts lights reaching
// this pixel with more than 1/1024 that the list lacks (the culling test's check).
#include "deferred/lights.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 lit;
layout(location = 1) out vec2 missing;  // x: culled but contributing lights, y: list length
uniform sampler2D albedo;
uniform sampler2D normal;
uniform sampler2D position;
layout(std430) readonly buffer tiles { uint words[]; };
const int kTile = 16, kMaxLights = 64;
const float kShininess = 32.0;
void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec4 nw = texelFetch(normal, px, 0);
    ivec2 tiles_xy = (ivec2(frame.resolution.xy) + kTile - 1) / kTile;
    uint base = uint((px.y / kTile) * tiles_xy.x + px.x / kTile) * uint(kMaxLights + 1), n = words[base];
    missing = vec2(0.0, float(n));
    if (nw.w == 0.0) {
        lit = vec4(0.0, 0.0, 0.0, 1.0);
        return;
    }
    vec4 mat = texelFetch(albedo, px, 0);
    vec3 p = texelFetch(position, px, 0).xyz, nrm = normalize(nw.xyz), v = normalize(frame.camera_pos.xyz - p);
    vec3 c = params.ambient * mat.rgb;
    for (uint k = 0u; k < n; ++k) c += shade_point_light(point_light(int(words[base + 1u + k]), frame.time), p, nrm, v, mat.rgb, mat.a, kShininess);
    for (int i = 0; params.verify && i < params.lights; ++i) {
        vec3 e = shade_point_light(point_light(i, frame.time), p, nrm, v, mat.rgb, mat.a, kShininess);
        if (max(e.r, max(e.g, e.b)) > 1.0 / 1024.0) {
            bool listed = false;
            for (uint k = 0u; k < n; ++k) listed = listed || words[base + 1u + k] == uint(i);
            missing.x += listed ? 0.0 : 1.0;
        }
    }
    lit = vec4(c, 1.0);
    if (params.show == SHOW_COUNT) lit = vec4(float(n) == 0.0 ? vec3(0.0) : mix(vec3(0.1, 0.2, 0.8), vec3(1.0, 0.15, 0.05), clamp(float(n) / 24.0, 0.0, 1.0)), 1.0);
}
