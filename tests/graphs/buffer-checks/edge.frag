#version 450
// Partial agreement: `reference` is a hard step at x = w/2 (a shadow-map edge); `approx` equals
// it except in a 4-px band around the edge, where it is the midpoint 0.5 (a filtered edge);
// `band` is 1 exactly in that band. Values 0.25/0.5/0.75 are exact in rgba16f.
layout(location = 0) out vec4 reference;
layout(location = 1) out vec4 approx;
layout(location = 2) out vec4 band;

void main() {
    float x = gl_FragCoord.x - frame.resolution.x * 0.5;  // pixel centres: -15.5 .. 15.5 at w = 32
    float ref = x < 0.0 ? 0.25 : 0.75;
    bool in_band = abs(x) < params.band_half;             // 2 px on either side of the edge
    reference = vec4(vec3(ref), 1.0);
    approx = vec4(vec3(in_band ? 0.5 : ref), 1.0);
    band = vec4(in_band ? 1.0 : 0.0);
}
