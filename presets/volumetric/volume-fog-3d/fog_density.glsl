// The fog box [-1, 1]^3 and its density (shared by the view march and the light bake).
#ifndef VOLUME_FOG_DENSITY_GLSL
#define VOLUME_FOG_DENSITY_GLSL
vec2 box_hit(vec3 o, vec3 d) {   // slab test against [-1, 1]^3: (t_near clamped to 0, t_far)
    vec3 inv = 1.0 / d, t0 = (-1.0 - o) * inv, t1 = (1.0 - o) * inv;
    vec3 lo = min(t0, t1), hi = max(t0, t1);
    return vec2(max(max(lo.x, lo.y), max(lo.z, 0.0)), min(min(hi.x, hi.y), hi.z));
}
// The texture's value shaped into puffs: smoothstep(0.4, 0.7, v), which keeps v = 1 at 1 (the
// homogeneous slab) and empties the space between puffs.
float rho(vec3 p) { return params.sigma * smoothstep(0.4, 0.7, texture(density, p * 0.5 + 0.5).r); }
#endif
