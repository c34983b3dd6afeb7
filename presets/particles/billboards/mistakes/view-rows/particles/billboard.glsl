// Billboards (impostors, sprites): a textured rectangle of two triangles that faces the viewer
// or turns about one axis (000_c9f7e5de708ecbb3.txt L3689-3731).
//
// The seed's recipe (L3708-3729) removes the rotation from the model-view matrix and keeps the
// scale: the upper 3x3 becomes diag(s0, s1, s2), so the quad's corners are offset along the
// camera's own x and y axes. In world space that is the same as offsetting the centre along the
// camera's right and up vectors, the first two columns of the inverse view matrix (the rows of
// the view matrix's rotation): the quad's normal is then the view's z axis exactly.
#ifndef PASSLAB_BILLBOARD_GLSL
#define PASSLAB_BILLBOARD_GLSL

// Corner of vertex v (0..5) of a quad drawn as two triangles, in [-1, 1]^2, counter-clockwise
// as seen by the viewer (front-facing with front_face = "ccw").
vec2 pl_quad_corner(int v) {
    const vec2 c[6] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, -1), vec2(1, 1), vec2(-1, 1));
    return c[v % 6];
}

// Screen-aligned (view-plane-aligned): corners along the camera's right and up axes; size is
// the half-width in world units, so the projected size falls off as 1 / distance.
vec3 pl_billboard_screen(vec3 centre, vec2 corner, float size, mat4 inv_view) {
    mat4 view = inverse(inv_view);
    // the first two columns of the VIEW matrix (not of its inverse): rows and columns swapped
    return centre + size * (corner.x * view[0].xyz + corner.y * view[1].xyz);
}

// Axis-aligned (cylindrical, trees and flames): the quad keeps `axis` as its up direction and
// turns about it to face the eye as far as it can: right = normalize(axis x to_eye).
vec3 pl_billboard_axis(vec3 centre, vec2 corner, float size, vec3 axis, vec3 eye) {
    vec3 right = normalize(cross(axis, eye - centre));
    return centre + size * (corner.x * right + corner.y * axis);
}
#endif
