#version 450
layout(location = 0) out vec4 color;
void main() {
    float big[500000000];
    for (int i = 0; i < 500000000; ++i) big[i] = float(i);
    color = vec4(big[int(gl_FragCoord.x)]);
}
