// Planar projected shadows (Blinn 1988; 000_c9f7e5de708ecbb3.txt L4483-4563): a matrix squashes
// the caster onto the receiver plane along the rays from the light, and the flat copy darkens
// the receiver.
//
// Onto y = 0 from a point light l, by similar triangles (L4497-4509):
//     p_x = (l_y v_x - l_x v_y) / (l_y - v_y),  p_z = (l_y v_z - l_z v_y) / (l_y - v_y),  p_y = 0
//     M = | l_y  -l_x  0    0   |
//         | 0     0    0    0   |        (L4511)
//         | 0    -l_z  l_y  0   |
//         | 0    -1    0    l_y |
// Onto a general plane n.p + d = 0 (L4515-4526): the ray p = l + alpha (v - l) meets it at
//     p = l - (d + n.l) / (n.(v - l)) (v - l)
// and as a matrix (L4526), with P = (n, d) and the light L = (l, 1),
//     M = (P.L) I - L P^T
// whose rows are the document's: diagonal n.l + d - l_i n_i, last column -l_i d, last row
// (-n, n.l). Check: M v = (n.l + d) v - l (n.v + d), w = n.l - n.v, and dividing by w gives the
// ray formula. The y = 0 matrix above is this one with n = (0, 1, 0), d = 0.
// Written with a homogeneous light L = (l, w) the same M also projects along a directional
// light's rays (w = 0, l towards the light): w = n.l, p = v - l (n.v + d) / (n.l).
//
// Pitfalls (L4555-4563): a vertex on the far side of the light (n.v > n.l, behind the light
// seen from the plane) gets w < 0 and lands on the plane's other side of the light: an
// "anti-shadow"; a caster part below the receiver is projected too ("objects behind
// receiver"), and nothing stops the flat copy from extending off a finite receiver
// (L4538-4539) unless the stencil restricts it (L4541-4551).
#ifndef PASSLAB_PLANAR_SHADOW_GLSL
#define PASSLAB_PLANAR_SHADOW_GLSL
// GLSL matrices are column-major: outerProduct(L, P)[j][i] = L_i P_j, row i column j, i.e. L P^T.
mat4 planar_shadow_matrix(vec4 plane, vec4 light) {
    return dot(plane, light) * mat4(1.0) - outerProduct(light, plane);
}
#endif
