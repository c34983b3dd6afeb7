// The cluster grid of clustered forward shading (002_644d46bdce7e5305.txt L21-22: the engine's
// "clustered forward" renderer, the 3D form of tiled forward shading, 003 L906-922): the view
// frustum cut into kTilePx x kTilePx-pixel tiles in x and y and kSlices slices in view depth.
// The slices are exponential: slice 1 .. kSlices - 2 span [z_near, z_far] with a constant
// ratio per slice,
//   d_k = z_near (z_far / z_near)^((k - 1) / (kSlices - 2)),   k = 1 + floor((kSlices - 2) log(d / z_near) / log(z_far / z_near)),
// so a cluster is about as deep as it is wide at every distance. Slice 0 holds everything
// nearer than z_near, slice kSlices - 1 everything beyond z_far.
#ifndef CLUSTERS_GLSL
#define CLUSTERS_GLSL

const int kTilePx = 32, kSlices = 16;
const int kMaxPerCluster = 64;  // = the most lights: a list never overflows
const float kFarAway = 1e5;     // depth bound of the last slice

ivec3 cluster_grid() { return ivec3((ivec2(frame.resolution.xy) + kTilePx - 1) / kTilePx, kSlices); }

int cluster_index(ivec3 c) {
    ivec3 g = cluster_grid();
    return (c.z * g.y + c.y) * g.x + c.x;
}

// The exponential range; z_far is kept above z_near (both are free params).
float slices_far() { return max(params.z_far, 1.01 * params.z_near); }

int slice_of(float d) {
    if (d < params.z_near) return 0;
    if (d >= slices_far()) return kSlices - 1;
    float s = log(d / params.z_near) / log(slices_far() / params.z_near);
    return clamp(1 + int(floor(s * float(kSlices - 2))), 1, kSlices - 2);
}

// View-depth interval [near, far] of slice k.
vec2 slice_depths(int k) {
    if (k == 0) return vec2(0.0, params.z_near);
    if (k == kSlices - 1) return vec2(slices_far(), kFarAway);
    float ratio = slices_far() / params.z_near;
    return params.z_near * vec2(pow(ratio, float(k - 1) / float(kSlices - 2)), pow(ratio, float(k) / float(kSlices - 2)));
}

// Cluster of a fragment: its tile, and the slice of its view depth d = -z_view.
ivec3 cluster_of(vec2 frag_coord, float d) { return ivec3(ivec2(frag_coord) / kTilePx, slice_of(d)); }

// The view-space box around cluster c: the four corner rays of its tile (unprojected through
// the inverse projection) cut at both depth bounds. The frustum piece lies inside this box,
// so a sphere missing the box misses the cluster (conservative). The box is padded by a
// millionth of its depth against the rounding of log/pow at slice boundaries.
void cluster_box(ivec3 c, out vec3 lo, out vec3 hi) {
    vec2 px0 = vec2(c.xy * kTilePx), px1 = min(vec2((c.xy + 1) * kTilePx), frame.resolution.xy);
    vec2 z = slice_depths(c.z);
    lo = vec3(1e30), hi = vec3(-1e30);
    for (int i = 0; i < 4; ++i) {
        vec2 ndc = vec2(i % 2 == 0 ? px0.x : px1.x, i / 2 == 0 ? px0.y : px1.y) * frame.resolution.zw * 2.0 - 1.0;
        vec4 q = frame.inv_proj * vec4(ndc, 0.5, 1.0);
        vec3 ray = (q.xyz / q.w) / (-q.z / q.w);  // the view point of this corner at depth 1
        lo = min(lo, min(ray * z.x, ray * z.y));
        hi = max(hi, max(ray * z.x, ray * z.y));
    }
    float pad = 1e-6 * z.y + 1e-6;
    lo -= pad, hi += pad;
}

// A light's sphere meets the box when the box point nearest to the centre is within reach.
bool sphere_meets_box(vec3 centre, float radius, vec3 lo, vec3 hi) {
    return distance(clamp(centre, lo, hi), centre) <= radius;
}
#endif
