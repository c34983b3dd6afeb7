#version 450
layout(location = 0) out vec4 color;
layout(std430) readonly buffer Counter { uint n; } counter;
layout(r32ui) uniform readonly uimage2D hits;
void main() {
    color = vec4(gl_FragCoord.x < 1.0 ? float(counter.n) : float(imageLoad(hits, ivec2(0)).r));
}
