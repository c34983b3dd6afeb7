#version 450
// Brute-force reference: the union of the puffs' projected discs, per pixel centre, without
// rasterising a quad. A disc of radius s centred at c in a plane parallel to the image plane
// projects to the ellipse centred at c's NDC with radii |P00| s / w and |P11| s / w (w = the
// clip w of c, its view depth): x_ndc = P00 (c_x + s cos t) / w, and likewise y.
#include "clouds.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
void main() {
    vec2 ndc = uv * 2.0 - 1.0;
    float inside = 0.0;
    for (int i = 0; i < PUFFS; ++i) {
        vec4 c = frame.view_proj * vec4(puff_centre(i), 1.0);
        if (c.w <= 0.0) continue;
        vec2 r = vec2(abs(frame.proj[0][0]), abs(frame.proj[1][1])) * puff_size(i) / c.w;
        vec2 d = (ndc - c.xy / c.w) / r;
        if (dot(d, d) <= 1.0) inside = 1.0;
    }
    color = vec4(inside, inside, inside, 1.0);
}
