#version 450
// params.iterations of an expensive body at every pixel: 60000 (below lavapipe's silent 65535
// loop cut-off) runs for many seconds per frame on a CPU driver; 1 finishes at once.
layout(location = 0) out vec4 color;
void main() {
    float acc = gl_FragCoord.x;
    for (int i = 0; i < params.iterations; ++i) {
        acc = sin(acc + float(i)) * cos(acc * 1.37) + exp(-abs(acc)) + sqrt(abs(acc) + 1.0);
        acc = sin(acc + float(i)) * cos(acc * 1.37) + exp(-abs(acc)) + sqrt(abs(acc) + 1.0);
        acc = sin(acc + float(i)) * cos(acc * 1.37) + exp(-abs(acc)) + sqrt(abs(acc) + 1.0);
        acc = sin(acc + float(i)) * cos(acc * 1.37) + exp(-abs(acc)) + sqrt(abs(acc) + 1.0);
    }
    color = vec4(params.iterations == 1 ? 0.25 : acc);
}
