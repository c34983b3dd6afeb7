#version 450
// The fullscreen triangle (000_c9f7e5de708ecbb3.txt L2900-2916), written out: the vertex stage
// kind = "fullscreen" passes otherwise get from the host (the same three corners and uv).
// Three vertices, no vertex buffer: gl_VertexIndex 0, 1, 2 gives the corner p = (0, 0), (2, 0),
// (0, 2) by bit tricks, p.x = (i << 1) & 2, p.y = i & 2. In clip space 2p - 1: (-1, -1), (3, -1),
// (-1, 3), a right triangle twice the screen's size whose legs pass through the screen's corners
// (-1, -1), (1, -1), (-1, 1), so its hypotenuse x + y = 2 passes through (1, 1): the screen is
// inside and the clipper trims the rest (no pixel outside the screen is shaded).
// uv = p: uv is the affine function of the clip position uv = (pos + 1) / 2, (0, 0) at the
// top-left corner of the screen (Vulkan's NDC y points down, as does the image's row) and (1, 1)
// at the bottom-right; interpolated, a pixel centre (x + 0.5, y + 0.5) gets uv = ((x + 0.5) / W,
// (y + 0.5) / H), the half-texel offset included.
layout(location = 0) out vec2 uv;
void main() {
    vec2 p = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
    uv = p;
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
