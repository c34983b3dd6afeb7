// The interpolated normal, or where it vanishes (the teapot generator's degenerate normals at the
// lid knob and the bottom pole) the face's own, from the position derivatives. Its orientation
// there is the screen's, so callers that need "outward" still faceforward it.
vec3 safe_normal(vec3 n, vec3 p) {
    return dot(n, n) > 1e-12 ? normalize(n) : normalize(cross(dFdx(p), dFdy(p)));
}
