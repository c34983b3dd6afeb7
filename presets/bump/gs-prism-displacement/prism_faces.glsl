// The side quad over edge (p_i, p_j) of a prism lifted along the vertex normals (q = p + n h)
// is not planar; it is drawn as two triangles, split along the diagonal p_i - q_j when
// prism_diagonal_from_i is true, else along p_j - q_i. The two prisms that share the edge must
// split it alike, or slivers open between them, so the choice depends on the unordered pair of
// corners: the diagonal starts at the lexicographically smaller one.
#ifndef PASSLAB_PRISM_FACES_GLSL
#define PASSLAB_PRISM_FACES_GLSL
bool corner_less(vec3 a, vec3 b) { return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z; }
bool prism_diagonal_from_i(vec3 p_i, vec3 p_j) { return corner_less(p_i, p_j); }
#endif
