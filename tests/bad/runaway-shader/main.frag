#version 450
// Runs for many seconds per frame on a CPU driver: 60000 iterations (below lavapipe's silent
// 65535 loop cut-off) of an expensive body, at every pixel.
layout(location = 0) out vec4 color;
void main() {
    float acc = gl_FragCoord.x;
    for (int i = 0; i < 60000; ++i) {
        acc = sin(acc + float(i)) * cos(acc * 1.37) + exp(-abs(acc)) + sqrt(abs(acc) + 1.0);
        acc = sin(acc + float(i)) * cos(acc * 1.37) + exp(-abs(acc)) + sqrt(abs(acc) + 1.0);
        acc = sin(acc + float(i)) * cos(acc * 1.37) + exp(-abs(acc)) + sqrt(abs(acc) + 1.0);
        acc = sin(acc + float(i)) * cos(acc * 1.37) + exp(-abs(acc)) + sqrt(abs(acc) + 1.0);
    }
    color = vec4(acc);
}
