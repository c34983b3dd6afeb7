#version 450
// Pass 2's colour: unlit ink (004 L1148: "switch to green colour for all geometry, no lighting"),
// and a 1 in the lines image for the tests.
layout(location = 0) out vec4 color;
layout(location = 1) out float lines;
void main() {
    color = vec4(params.ink, 1.0);
    lines = 1.0;
}
