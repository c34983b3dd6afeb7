#version 450
// Test-only: how far the imperfect shadow maps are from the triangle-rendered paraboloid maps of
// the same VPLs (the catalogue's invariant: >= 95% of texels match), and whether pull-push
// touched a texel that held a point. One work group of 256 threads walks every texel of every
// live slot and reduces in shared memory into the buffer `ism_match`:
//   [0] matched / queried   over the texels the gather can look up: inside the paraboloid's disc
//                           (|(s,t)| < 1) and where the triangle map holds a surface (< 1); the
//                           box is open at the front, and what lies beyond it is never a
//                           receiver, so those texels (and the corners outside the disc, always
//                           1 = 1) would match trivially or not matter: they are not counted
//   [1] matched / disc      over every texel inside the disc (the open front counted too)
//   [2] queried, [3] disc   the counts
//   [4] changed             texels with a point before pull-push (ism_push < 1) whose value after
//                           it (ism_pull) differs: 0 if pull-push only fills holes
//   [5] the share of the queried texels that a splat covered (the rest pull-push filled)
//   [6] matched / queried among those covered texels (the splats' own accuracy)
// A texel matches when |d_ism - d_tri| < the gather's own compare bias at that distance,
// (3 cm + 6% of the distance) / VPL_FAR (gi/vpl_gather.glsl): the error below which the two maps
// give every receiver on that ray the same visibility.
// Each thread walks texels / 256 texels: within llvmpipe's 65535 loop iterations per invocation
// (instant-radiosity's README) up to 1024 slots of 64x64 maps or 256 of 128x128.
layout(local_size_x = 256) in;
#include "gi/vpl.glsl"
uniform sampler2DArray ism, ism_fine, tri_maps;  // P_0 (after pull-push), D_0 (before), triangles
layout(std430) buffer IsmMatch { float v[8]; } ism_match;
shared uint s_count[7][256];
void main() {
    uint t = gl_LocalInvocationIndex;
    ivec2 size = textureSize(ism, 0).xy;
    uint texels = uint(size.x * size.y) * vpl_args.slots;
    uint c[7] = uint[7](0u, 0u, 0u, 0u, 0u, 0u, 0u);  // matched (queried), queried, matched (disc), disc, changed,
                                                   // queried texels that held a point, and of those matched
    for (uint i = t; i < texels; i += 256u) {
        ivec3 q = ivec3(int(i) % size.x, (int(i) / size.x) % size.y, int(i) / (size.x * size.y));
        if (vpls.vpl[q.z].position.w <= 0.0) continue;
        // the texel's centre in the map's (s, t): gi/vpl_gather.glsl looks up uv = (0.5 + s/2, 0.5 - t/2)
        vec2 st = vec2((float(q.x) + 0.5) / float(size.x) * 2.0 - 1.0, 1.0 - (float(q.y) + 0.5) / float(size.y) * 2.0);
        float before = texelFetch(ism_fine, q, 0).r, after = texelFetch(ism, q, 0).r;
        if (before < 1.0 && after != before) c[4]++;
        if (dot(st, st) >= 1.0) continue;
        float tri = texelFetch(tri_maps, q, 0).r;
        bool match = abs(after - tri) < (0.03 + 0.06 * tri * VPL_FAR) / VPL_FAR;
        if (tri < 1.0) { c[1]++; if (match) c[0]++; if (before < 1.0) { c[5]++; if (match) c[6]++; } }
        c[3]++; if (match) c[2]++;
    }
    for (int k = 0; k < 7; ++k) s_count[k][t] = c[k];
    barrier();
    for (uint w = 128u; w > 0u; w >>= 1) {
        if (t < w) for (int k = 0; k < 7; ++k) s_count[k][t] += s_count[k][t + w];
        barrier();
    }
    if (t == 0u) {
        ism_match.v[0] = float(s_count[0][0]) / max(float(s_count[1][0]), 1.0);
        ism_match.v[1] = float(s_count[2][0]) / max(float(s_count[3][0]), 1.0);
        ism_match.v[2] = float(s_count[1][0]);
        ism_match.v[3] = float(s_count[3][0]);
        ism_match.v[4] = float(s_count[4][0]);
        ism_match.v[5] = float(s_count[5][0]) / max(float(s_count[1][0]), 1.0);
        ism_match.v[6] = float(s_count[6][0]) / max(float(s_count[5][0]), 1.0);
    }
}
