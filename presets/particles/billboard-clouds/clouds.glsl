// The cloud: PUFFS view-aligned billboards (000_c9f7e5de708ecbb3.txt L3733-3739: clouds drawn
// as many opaque billboards, each the image of a round puff), placed by a fixed hash inside a
// flattened ellipsoid. Shared by the draw (puff.vert) and the brute-force union (union.frag), so
// both see the same centres and sizes.
#include "particles/billboard.glsl"

#include "common/hash.glsl"
// Uniform in [0, 1): integer hash only (common/hash.glsl, PCG3D), the same bits on every device.
float pl_cloud_unit(uint i, uint k) { return float(pcg3d(uvec3(i, k, 7u)).x) * (1.0 / 4294967296.0); }

vec3 puff_centre(int i) {
    uint u = uint(i);
    vec3 r = vec3(pl_cloud_unit(u, 0u), pl_cloud_unit(u, 1u), pl_cloud_unit(u, 2u)) * 2.0 - 1.0;
    return vec3(2.2 * r.x, 0.35 * r.y + 0.25 * (1.0 - abs(r.x)), 0.9 * r.z);
}
float puff_size(int i) { return params.size * (0.6 + 0.6 * pl_cloud_unit(uint(i), 3u)); }
