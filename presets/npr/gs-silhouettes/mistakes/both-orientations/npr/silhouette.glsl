// The silhouette predicate shared by the geometry shaders that find silhouette edges
// (npr/silhouette.geom, particles/fins.geom) and the brute-force counts that check them
// (004_9a40ad89bdfc582a.txt L1098-1104: silhouette <=> e.n1 > 0 and e.n2 < 0, e = from the edge
// to the eye). `precise` keeps the arithmetic identical in every shader that includes this, so a
// brute-force count over the same corners agrees with the geometry shader's bit for bit.
#ifndef PASSLAB_SILHOUETTE_GLSL
#define PASSLAB_SILHOUETTE_GLSL
// Ortho projections have proj[3][3] = 1: every view ray is parallel.
vec3 to_eye(vec3 p) {
    return frame.proj[3][3] == 1.0 ? (frame.inv_view * vec4(0.0, 0.0, 1.0, 0.0)).xyz : frame.camera_pos.xyz - p;
}

bool faces_eye(vec3 a, vec3 b, vec3 c, float tol) {
    precise vec3 n = cross(b - a, c - a);
    precise vec3 v = to_eye(a);
    precise float d = dot(n, v);
    precise float limit = tol * length(n) * length(v);
    return d > limit;
}

#endif
