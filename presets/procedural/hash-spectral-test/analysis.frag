#version 450
// Per cell of the 32 x 32 histogram (image row 0 = the top row of the plot, y = 31/32..1):
//   density = O * 1024 / N          1 for a uniform generator (docs/catalogue.md: 1/1024 +- 10%)
//   chi     = (O - E)^2 / E          E = N / 1024; the mean over cells is chi^2 / 1024, whose
//                                    expectation for independent uniform points is 1023/1024
layout(std430) readonly buffer Histogram { uint cells[1024]; } histogram;
layout(location = 0) out float density;
layout(location = 1) out float chi;
void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    uint observed = histogram.cells[(31 - px.y) * 32 + px.x];
    float expected = float(params.count) / 1024.0;
    density = float(observed) / expected;
    float d = float(observed) - expected;
    chi = d * d / expected;
}
