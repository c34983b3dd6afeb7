#version 450
// The maps as an atlas, one tile per live VPL slot in a square grid (params.show):
//   atlas  the imperfect shadow maps after pull-push (ism_pull level 0): depth, near = bright;
//          holes that pull-push left (or with pullpush off) in blue
//   diff   against the triangle maps of the same VPLs (tri_maps): green where the two agree
//          within the gather's bias (as ism_match.comp counts), red where they do not, grey for
//          texels the gather never looks up (outside the disc, or beyond the box's open front)
#include "gi/vpl.glsl"
layout(location = 0) in vec2 uv;
uniform sampler2DArray ism, tri_maps;
layout(location = 0) out vec4 o_ldr;
void main() {
    int slots = int(vpl_args.slots);
    int grid = int(ceil(sqrt(float(slots))));
    vec2 a = uv * vec2(frame.resolution.x / frame.resolution.y, 1.0) * float(grid);
    ivec2 tile = ivec2(floor(a));
    int s = tile.y * grid + tile.x;
    if (tile.x >= grid || s >= slots) { o_ldr = vec4(0.0, 0.0, 0.0, 1.0); return; }
    vec2 f = fract(a);
    ivec2 size = textureSize(ism, 0).xy;
    ivec3 q = ivec3(min(ivec2(f * vec2(size)), size - 1), s);
    float d = texelFetch(ism, q, 0).r, tri = texelFetch(tri_maps, q, 0).r;
    vec2 st = vec2(f.x * 2.0 - 1.0, 1.0 - f.y * 2.0);
    vec3 c;
    if (params.show == SHOW_DIFF) {
        bool match = abs(d - tri) < (0.03 + 0.06 * tri * VPL_FAR) / VPL_FAR;
        c = dot(st, st) >= 1.0 || tri >= 1.0 ? vec3(0.15) : match ? vec3(0.1, 0.7, 0.1) : vec3(0.9, 0.1, 0.1);
    } else {
        c = d >= 1.0 ? vec3(0.0, 0.0, 0.4) : vec3(1.0 - d);
    }
    if (vpls.vpl[s].position.w <= 0.0) c *= 0.2;
    o_ldr = vec4(c, 1.0);
}
