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
    float det = u1.x * u2.y - u2.x * u1.y;   // |u1 u2|
    const float kDegenerate = 1e-6;          // relative area below which a triangle has no frame
    if (abs(det) < 1e-12 || length(cross(v1, v2)) < kDegenerate * (dot(v1, v1) + dot(v2, v2)))
        return mat2x3(vec3(0.0), vec3(0.0));
    mat2 inv = mat2(u2.y, -u1.y, -u2.x, u1.x);   // columns: (u2.y, -u1.y), (-u2.x, u1.x)
    return mat2x3(v1, v2) * inv;
}

// The handedness of a frame: +1 when B = N x T points along P_v (right-handed (u, v) on the
// surface), -1 when the parameterisation is mirrored (B = -(N x T)). Store it with T (the
// tangent's w) and rebuild B = (N x T) w, or mirrored uv islands light from the wrong side.
float frame_handedness(vec3 N, vec3 T, vec3 P_v) { return dot(cross(N, T), P_v) < 0.0 ? -1.0 : 1.0; }
#endif
