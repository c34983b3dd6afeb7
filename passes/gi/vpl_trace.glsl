// Ray queries against the Cornell box (gi/cornell.glsl) through the host-built BVH: the graph
// declares `scene = { generator = "bvh", meshes = ["wall", "block"] }` (mesh 0 = the `plane`
// walls, mesh 1 = the `cube` blocks), and each instance is traced in its object space with the
// inverse of its placement (docs/format.md, host-built scene buffers).
#ifndef PASSLAB_GI_VPL_TRACE_GLSL
#define PASSLAB_GI_VPL_TRACE_GLSL
#include "raytrace/bvh.glsl"
#include "gi/cornell.glsl"

struct VplSurface {
    bool hit;
    vec3 p, n, albedo;  // world point, unit normal (facing into the box / out of a block), rho
};

mat4 vpl_placement(int instance) {
    return instance < CORNELL_WALLS ? cornell_wall(instance) : cornell_block(instance - CORNELL_WALLS);
}

// The nearest surface along ro + t rd, t > tmin.
VplSurface vpl_trace(vec3 ro, vec3 rd, float tmin) {
    PlHit h = pl_no_hit(1e30);
    for (int i = 0; i < CORNELL_WALLS + CORNELL_BLOCKS; ++i)
        pl_bvh_closest(i < CORNELL_WALLS ? 0u : 1u, inverse(vpl_placement(i)), i, ro, rd, tmin, h);
    VplSurface s = VplSurface(false, vec3(0.0), vec3(0.0, 1.0, 0.0), vec3(0.0));
    if (h.instance < 0) return s;
    mat4 m = vpl_placement(h.instance);
    s.hit = true;
    s.p = ro + rd * h.t;
    vec3 n_obj = vec3(0.0, 1.0, 0.0);  // the plane's normal
    if (h.instance >= CORNELL_WALLS) {  // a cube face: the object-space point's dominant axis
        vec3 q = (inverse(m) * vec4(s.p, 1.0)).xyz, a = abs(q);
        n_obj = a.x > a.y && a.x > a.z ? vec3(sign(q.x), 0, 0) : a.y > a.z ? vec3(0, sign(q.y), 0) : vec3(0, 0, sign(q.z));
    }
    s.n = normalize(transpose(inverse(mat3(m))) * n_obj);
    bool block = h.instance >= CORNELL_WALLS;
    s.albedo = cornell_albedo(block ? 1 : 0, block ? h.instance - CORNELL_WALLS : h.instance);
    return s;
}

// Whether the segment a -> b is free of surfaces (both ends excluded by a small margin).
bool vpl_visible(vec3 a, vec3 b) {
    vec3 d = b - a;
    for (int i = 0; i < CORNELL_WALLS + CORNELL_BLOCKS; ++i)
        if (pl_bvh_occluded(i < CORNELL_WALLS ? 0u : 1u, inverse(vpl_placement(i)), a, d, 1e-3, 1.0 - 1e-3)) return false;
    return true;
}

// Direct radiance-times-pi/rho of the spot at a traced surface point: E_direct, ray-traced shadow.
vec3 vpl_direct_irradiance(vec3 p, vec3 n) {
    return vpl_visible(p + n * 1e-3, CORNELL_LIGHT_POS) ? cornell_light_irradiance(p, n) : vec3(0.0);
}

float vpl_radical_inverse(uint i) { return float(bitfieldReverse(i)) * 2.3283064e-10; }
uint vpl_hash(uint x) {
    x ^= x >> 16; x *= 0x7feb352du; x ^= x >> 15; x *= 0x846ca68bu; x ^= x >> 16;
    return x;
}

// A unit vector with density cos(theta)/pi about n from a point u of the unit square.
vec3 vpl_cosine_direction(vec3 n, vec2 u) {
    float r = sqrt(u.x), phi = 6.2831853 * u.y;
    vec3 t = normalize(abs(n.x) > 0.5 ? cross(n, vec3(0, 1, 0)) : cross(n, vec3(1, 0, 0)));
    vec3 b = cross(n, t);
    return normalize(t * r * cos(phi) + b * r * sin(phi) + n * sqrt(max(1.0 - u.x, 0.0)));
}
#endif
