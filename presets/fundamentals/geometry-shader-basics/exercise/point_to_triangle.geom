#version 450
// EXERCISE — this file shadows the preset's point_to_triangle.geom (TODO 1-2); shrink.geom next
// to it holds TODO 3-4.
//     passlab run   fundamentals/geometry-shader-basics --exercise presets/fundamentals/geometry-shader-basics/exercise
//     passlab grade fundamentals/geometry-shader-basics --exercise presets/fundamentals/geometry-shader-basics/exercise
// "A very simple geometry shader program" (004_9a40ad89bdfc582a.txt L1021-1040): every point
// becomes a triangle with corners at clip-space offsets (0, d), (d, -d), (-d, -d), coloured red,
// green, blue. Ported from #version 120 + GL_EXT_geometry_shader4 (docs/catalogue.md pitfall):
//   gl_PositionIn[0]      -> gl_in[0].gl_Position
//   gl_FrontColor         -> a user output (location 0)
//   GL_GEOMETRY_INPUT_TYPE / OUTPUT_TYPE / VERTICES_OUT (L905-925, L1003-1013)
//                         -> the layout qualifiers below: max_vertices must be declared
//                            (at most 1024 output vertices, L876).
// In NDC the triangle has base 2d and height 2d: area 2 d^2 of the 4 the view spans, so
// d^2/2 of the view's pixels (w = 1: the offsets are not divided by anything). Vulkan's NDC y
// points down, so the printed offsets are flipped in y (kUp) to keep the slide's apex-up
// picture; that does not change the area.
layout(points) in;
layout(triangle_strip, max_vertices = 3) out;
layout(location = 0) out vec3 g_color;
const float kUp = -1.0;
void main() {
    if (gl_in[0].gl_Position.z < -1.0) return;          // hidden pass (VISIBLE false)
    float d = params.d;                                   // printed: 0.04
    // TODO 1: emit the triangle (004 L1021-1040): three vertices at the point's clip position
    // plus the offsets (0, d), (d, -d), (-d, -d), coloured red, green, blue in that order. Each
    // vertex is its outputs (gl_Position, g_color) written, then EmitVertex(). The printed
    // offsets assume y up; Vulkan's NDC y points down: scale every y offset by kUp so the apex
    // stays on top, as on the slide.

    // TODO 2: end the primitive: close the triangle strip of TODO 1 (004 L1021-1040).
}
