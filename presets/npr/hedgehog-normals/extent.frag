#version 450
// Test read-out. Texel 0: the lines' extent in pixels (x, y = columns and rows covered) and the
// same in world units at the orthographic scale (z, w): pixels / (|P00| w / 2), / (|P11| h / 2).
// Texel 1: x = the lines' support along the diagonal (1, 1) / sqrt 2 from the view's centre, in
// world units (square views).
layout(location = 0) out vec4 extent;
layout(std430) readonly buffer line_bounds { uint bounds[5]; };
const float kBias = 65536.0;
void main() {
    vec2 last = frame.resolution.xy - 1.0;
    vec2 lo = last - vec2(bounds[2], bounds[3]), hi = vec2(bounds[0], bounds[1]);
    vec2 pixels = hi - lo + 1.0;
    // Orthographic: P00 = 2 / width, P11 = -2 / height of the view volume.
    vec2 px_per_unit = vec2(abs(frame.proj[0][0]), abs(frame.proj[1][1])) * frame.resolution.xy * 0.5;
    extent = vec4(pixels, pixels / px_per_unit);
    if (int(gl_FragCoord.x) == 1) extent = vec4((float(bounds[4]) - kBias) / 16.0 / sqrt(2.0) / px_per_unit.y, 0.0, 0.0, 0.0);
}
