#version 450
// The scatter plot of L661-664: vertex i is the plotted point of indices (i, i+1, i+2), one
// pixel, added into the plot image: the first vertex_count (preset.toml) points only; the
// histogram has all params.count of them.
#include "sequences.glsl"
void main() {
    Sequence s = sequence_at(uint(gl_VertexIndex));
    uint u0 = sequence_next(s), u1 = sequence_next(s), u2 = sequence_next(s);
    vec2 p = vec2(plotted_point(u0, u1, u2)) / kTwo32;
    gl_Position = vec4(2.0 * p.x - 1.0, 1.0 - 2.0 * p.y, 0.0, 1.0);  // y up, as in a plot
    gl_PointSize = 1.0;
}
