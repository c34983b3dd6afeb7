// The tangent frame of one triangle from its positions and texture coordinates
// (001_fe43b953f362fae7.txt L801-855): inside a triangle P(s, t) = a s + b t + c is linear, so
// P_u = a, P_v = b; with the edges
//     u1 = t1 - t0, u2 = t2 - t0      (texture space)       v1 = p1 - p0, v2 = p2 - p0   (object space)
//     [P_u P_v] [u1 u2] = [v1 v2]   =>   [P_u P_v] = [v1 v2] [u1 u2]^-1,
//     [u1 u2]^-1 = 1 / |u1 u2| * [ u2.y  -u2.x ]
//                                [ -u1.y  u1.x ]
// then T = P_u / |P_u|, B = N_n x T (L849-855). A mesh averages this over the triangles around
// each vertex, like normals (L857-862; host/scene/generators.cpp compute_tangents).
#ifndef PASSLAB_TRIANGLE_FRAME_GLSL
#define PASSLAB_TRIANGLE_FRAME_GLSL

// Returns the columns P_u, P_v; zero when the triangle is degenerate in uv (no inverse) or in
// space (two corners in one point, as at a sphere's poles: P_u is then 0 or rounding noise).
mat2x3 triangle_pu_pv(vec3 p0, vec3 p1, vec3 p2, vec2 t0, vec2 t1, vec2 t2) {
    vec3 v1 = p1 - p0, v2 = p2 - p0;
    vec2 u1 = t1 - t0, u2 = t2 - t0;
    // EXERCISE (bump/tangent-frame): TODO 1-2 here, TODO 3 in tangent_space.vert next to this
    // file (both shadow passes/bump/).
    //     passlab run   bump/tangent-frame --exercise presets/bump/tangent-frame/exercise
    //     passlab grade bump/tangent-frame --exercise presets/bump/tangent-frame/exercise
    // TODO 1: solve [P_u P_v] [u1 u2] = [v1 v2] for P_u, P_v (001 L831-846): det = |u1 u2|, the
    // determinant of the 2 x 2 matrix whose columns are u1 and u2, and
    //     [u1 u2]^-1 = 1/|u1 u2| [ u2.y  -u2.x ]      (rows as printed in 001 L844-846;
    //                            [ -u1.y  u1.x ]       GLSL's mat2(a, b, c, d) takes COLUMNS)
    // Keep the guard: a triangle degenerate in uv (|det| < 1e-12) or in space (area below
    // 1e-6 (|v1|^2 + |v2|^2), a sphere's pole) has no frame: return two zero columns.
    // Return the columns P_u, P_v.
    return mat2x3(vec3(0.0), vec3(0.0));
}

// The handedness of a frame: +1 when B = N x T points along P_v (right-handed (u, v) on the
// surface), -1 when the parameterisation is mirrored (B = -(N x T)). Store it with T (the
// tangent's w) and rebuild B = (N x T) w, or mirrored uv islands light from the wrong side.
float frame_handedness(vec3 N, vec3 T, vec3 P_v) {
    // TODO 2: 001 L853 builds B = N_n x T. Return +1 when that B points along P_v (the same
    // half space), -1 when it points against it (mirrored uv: B must be flipped). Nothing else.
    return 0.0;
}
#endif
