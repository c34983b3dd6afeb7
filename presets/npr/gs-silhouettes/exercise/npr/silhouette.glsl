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
    // EXERCISE (npr/gs-silhouettes). TODO 1: does the triangle (a, b, c), wound counter-clockwise
    // as seen from its front, face the eye? Its face normal n is the cross product of its edges
    // from a, in the order that makes n point out of a counter-clockwise front face; v = to_eye(a).
    // Front-facing when e.n > 0 (004_9a40ad89bdfc582a.txt L1094, e from the edge to the eye),
    // and with the tolerance of L1153: n.v > tol |n| |v| (tol = 0: the plain sign test).
    // Keep `precise` on every intermediate (see the comment above).
    return true;
}

#endif
