#version 450
// The 2x2 texture: red = column, green = row.
layout(location = 0) out vec4 ramp;
void main() { ramp = vec4(floor(gl_FragCoord.x), floor(gl_FragCoord.y), 0.0, 1.0); }
