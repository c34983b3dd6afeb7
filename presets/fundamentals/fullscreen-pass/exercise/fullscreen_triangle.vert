#version 450
// EXERCISE — the fullscreen triangle (000_c9f7e5de708ecbb3.txt L2900-2916). This file shadows the
// preset's fullscreen_triangle.vert, the vertex stage of its `triangle` and `uv` passes (the
// quad, for comparison, is drawn by passes/test/quad.vert and is not yours).
//     passlab run   fundamentals/fullscreen-pass --exercise presets/fundamentals/fullscreen-pass/exercise
//     passlab grade fundamentals/fullscreen-pass --exercise presets/fundamentals/fullscreen-pass/exercise
// Three vertices, no vertex buffer: everything comes from gl_VertexIndex = 0, 1, 2. The pass
// never culls, so the winding does not matter.
layout(location = 0) out vec2 uv;
void main() {
    // TODO 1: the corner p of vertex gl_VertexIndex: (0, 0), (2, 0), (0, 2) for 0, 1, 2 (a table,
    // or the bit tricks p.x = (i << 1) & 2, p.y = i & 2).
    vec2 p = vec2(0.0);
    // TODO 2: the clip-space position, 2p - 1: a right triangle (-1, -1), (3, -1), (-1, 3), twice
    // the screen's size, whose hypotenuse passes through the screen's corner (1, 1); the clipper
    // trims the rest (z = 0, w = 1).
    gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
    // TODO 3: uv, the affine function of the clip position that is (0, 0) at the screen's
    // top-left corner and (1, 1) at its bottom-right (Vulkan's NDC y points down, as the image's
    // rows do), so that the interpolated uv at a pixel centre (x + 0.5, y + 0.5) is
    // ((x + 0.5) / W, (y + 0.5) / H). What is it at the three corners of TODO 2?
    uv = vec2(0.0);
}
