// Octahedral normal encoding (Meyer et al. 2010; Cigolle et al. 2014): a unit vector onto the
// octahedron |x| + |y| + |z| = 1, the lower half folded over the upper, flattened to [-1, 1]^2.
// Two numbers instead of three and no sign ambiguity — unlike storing x, y and rebuilding
// z = sqrt(1 - x^2 - y^2), which fails for view-space normals pointing slightly away from the
// camera at silhouettes under perspective (003's example layout stores X, Y as FP16).
#ifndef PASSLAB_OCTAHEDRAL_GLSL
#define PASSLAB_OCTAHEDRAL_GLSL
vec2 oct_wrap(vec2 v) { return (1.0 - abs(v.yx)) * vec2(v.x >= 0.0 ? 1.0 : -1.0, v.y >= 0.0 ? 1.0 : -1.0); }
vec2 oct_encode(vec3 n) {
    n /= abs(n.x) + abs(n.y) + abs(n.z);
    return n.z >= 0.0 ? n.xy : oct_wrap(n.xy);
}
vec3 oct_decode(vec2 e) {
    vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));
    float t = clamp(-n.z, 0.0, 1.0);
    n.xy += vec2(n.x >= 0.0 ? -t : t, n.y >= 0.0 ? -t : t);
    return normalize(n);
}
#endif
