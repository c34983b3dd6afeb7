#version 450
// Tests: the baked table's row for si = max_taps, in the gather's indexing, against taps.frag's
// direct evaluation: |difference| per tap (0 if the gather reads the taps the tests check).
layout(location = 0) out float table_diff;
uniform sampler2D taps;
uniform sampler2D tap_table;
void main() {
    ivec2 s = ivec2(gl_FragCoord.xy);
    int row = params.max_taps + 1;
    vec2 from_table = texelFetch(tap_table, ivec2(s.y * row + s.x, params.max_taps - 2), 0).xy;
    table_diff = length(from_table - texelFetch(taps, s, 0).xy);
}
