// Any-hit ray casts against analytic primitives, for baking visibility (ambient occlusion
// "occlusion feelers", 004_9a40ad89bdfc582a.txt L703-715; 000_c9f7e5de708ecbb3.txt L4882-4883:
// "ordinary raycasting with maximal distance"). Each returns true when the ray o + t w,
// |w| = 1, meets the primitive at some t in (kRayTMin, t_max]. Callers start the ray a little
// off the surface (along its normal) so the surface never hits itself.
#ifndef PASSLAB_AO_RAYCAST_GLSL
#define PASSLAB_AO_RAYCAST_GLSL

const float kRayTMin = 0.0;

// Sphere |x - c| = r: t^2 + 2 b t + q = 0 with b = (o - c).w, q = |o - c|^2 - r^2.
bool ray_hits_sphere(vec3 o, vec3 w, vec3 c, float r, float t_max) {
    vec3 oc = o - c;
    float b = dot(oc, w), q = dot(oc, oc) - r * r, disc = b * b - q;
    if (disc < 0.0) return false;
    float s = sqrt(disc), t0 = -b - s, t1 = -b + s;
    return (t0 > kRayTMin && t0 <= t_max) || (t1 > kRayTMin && t1 <= t_max);
}

// Axis-aligned box (centre c, half extents h), slab test; solid, so an origin inside hits.
bool ray_hits_box(vec3 o, vec3 w, vec3 c, vec3 h, float t_max) {
    // A zero component would give 0 * inf = NaN for an origin on a slab plane: nudge it.
    vec3 ws = mix(w, sign(w + 1e-30) * 1e-20, lessThan(abs(w), vec3(1e-20)));
    vec3 inv = 1.0 / ws, ta = (c - h - o) * inv, tb = (c + h - o) * inv;
    vec3 tn = min(ta, tb), tf = max(ta, tb);
    float t_near = max(max(tn.x, tn.y), tn.z), t_far = min(min(tf.x, tf.y), tf.z);
    return t_near <= t_far && t_far > kRayTMin && max(t_near, kRayTMin) <= t_max;
}

// The square |x - c.x| <= h, |z - c.z| <= h of the plane y = c.y, both sides.
bool ray_hits_square_y(vec3 o, vec3 w, vec3 c, float h, float t_max) {
    if (w.y == 0.0) return false;
    float t = (c.y - o.y) / w.y;
    vec3 x = o + t * w;
    return t > kRayTMin && t <= t_max && abs(x.x - c.x) <= h && abs(x.z - c.z) <= h;
}

// A hemispherical bowl: the part y <= c.y of the sphere |x - c| = r, a shell of no thickness
// (both sides occlude); either root counts when its point lies in the lower half.
bool ray_hits_bowl(vec3 o, vec3 w, vec3 c, float r, float t_max) {
    vec3 oc = o - c;
    float b = dot(oc, w), q = dot(oc, oc) - r * r, disc = b * b - q;
    if (disc < 0.0) return false;
    float s = sqrt(disc), t0 = -b - s, t1 = -b + s;
    bool h0 = t0 > kRayTMin && t0 <= t_max && oc.y + t0 * w.y <= 0.0;
    bool h1 = t1 > kRayTMin && t1 <= t_max && oc.y + t1 * w.y <= 0.0;
    return h0 || h1;
}
#endif
