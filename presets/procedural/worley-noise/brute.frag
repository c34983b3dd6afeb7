#version 450
// Test reference for the search radius: F1, F2, F3 by brute force over the 9 x 9 cells around
// p (every feature point within 3 cells in x and y of p's own cell's neighbours and beyond),
// selected from all 81 distances without the running sort of worley_noise. The lab's 5 x 5
// search must give the same three values; a 3 x 3 search (the listing's, enough for F1 only)
// gets F2 or F3 wrong where the k-th nearest point lies two cells away.
#include "common/noise.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 brute;
void main() {
    vec2 p = (uv - 0.5) * vec2(frame.aspect, 1.0) * params.frequency + 100.0;  // as worley.frag
    vec2 c = floor(p);
    float d[81];
    for (int y = -4; y <= 4; ++y)
        for (int x = -4; x <= 4; ++x) d[(y + 4) * 9 + x + 4] = length(worley_point(c + vec2(x, y)) - p);
    vec3 f;
    float last = -1.0;
    int last_i = -1;
    for (int k = 0; k < 3; ++k) {  // the k-th smallest: the smallest after the (k-1)-th, ties by index
        float best = 1e9;
        int best_i = -1;
        for (int i = 0; i < 81; ++i)
            if ((d[i] > last || (d[i] == last && i > last_i)) && d[i] < best) { best = d[i]; best_i = i; }
        f[k] = best;
        last = best;
        last_i = best_i;
    }
    brute = vec4(f, 0.0);
}
