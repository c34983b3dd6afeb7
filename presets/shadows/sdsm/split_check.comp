#version 450
// Test-only: the logarithmic split distances of 002_644d46bdce7e5305.txt L1871-1873, L1893,
// z_i = zmin * (zmax / zmin)^(i / N), computed here independently of cascades.glsl (as
// exp(mix(log zmin, log zmax, i / N))), against what the fit recorded in `splits`:
// split_error[i] = |splits.z[2 + i] - z_i| for i = 0..N.
layout(local_size_x = 1) in;
layout(std430) readonly buffer Splits { float z[7]; } splits;
layout(std430) writeonly buffer SplitError { float e[5]; } split_error;
void main() {
    float zmin = splits.z[0], zmax = splits.z[1];
    for (int i = 0; i <= N; ++i)
        split_error.e[i] = abs(splits.z[2 + i] - exp(mix(log(zmin), log(zmax), float(i) / float(N))));
    for (int i = N + 1; i < 5; ++i) split_error.e[i] = 0.0;
}
