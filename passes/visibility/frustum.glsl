// The view frustum as six planes and the box-against-frustum test (000_c9f7e5de708ecbb3.txt
// L6056-6100: view-frustum culling; intersect(node, frustum)).
//
// Planes from the clip matrix M = view_proj (Gribb & Hartmann): a point is inside when
// -w <= x <= w, -w <= y <= w and 0 <= z <= w (Vulkan's depth range), i.e. for the rows r_i of M:
// (r3 + r0).p >= 0, (r3 - r0).p >= 0, (r3 + r1).p >= 0, (r3 - r1).p >= 0, r2.p >= 0, (r3 - r2).p >= 0.
// A box is outside when it lies wholly behind one plane: test its corner farthest along the
// plane's normal (the "p-vertex"). The test is conservative: a box outside the frustum but not
// behind any single plane (near an edge) counts as intersecting.
#ifndef PASSLAB_FRUSTUM_GLSL
#define PASSLAB_FRUSTUM_GLSL
vec4 pl_row(mat4 m, int i) { return vec4(m[0][i], m[1][i], m[2][i], m[3][i]); }

void pl_frustum_planes(mat4 m, out vec4 planes[6]) {
    vec4 r0 = pl_row(m, 0), r1 = pl_row(m, 1), r2 = pl_row(m, 2), r3 = pl_row(m, 3);
    planes[0] = r3 + r0; planes[1] = r3 - r0;
    planes[2] = r3 + r1; planes[3] = r3 - r1;
    planes[4] = r2;      planes[5] = r3 - r2;
}

// false when the box [lo, hi] is certainly outside (EMPTY intersection).
bool pl_box_intersects_frustum(vec3 lo, vec3 hi, vec4 planes[6]) {
    for (int k = 0; k < 6; ++k) {
        vec3 p = mix(lo, hi, greaterThanEqual(planes[k].xyz, vec3(0.0)));   // the p-vertex
        if (dot(planes[k].xyz, p) + planes[k].w < 0.0) return false;
    }
    return true;
}
#endif
