#version 450
// A fin's strands: the same tapering strands as the shells, seen from the side (a strand cell
// every 1 / fin_cells along the edge, height t up the fin), alpha-tested.
#include "particles/fur.glsl"
layout(location = 0) in vec2 fin_st;
layout(location = 1) in vec3 fin_normal;
layout(location = 0) out vec4 color;
void main() {
    float t = max(fin_st.y, 1e-3);
    if (!fur_strand(vec2(fin_st.x, 0.5), t)) discard;
    float lambert = max(dot(normalize(fin_normal), normalize(vec3(0.5, 0.8, 0.4))), 0.0);
    color = vec4(fur_color(t, lambert), 1.0);
}
