#version 450
layout(location = 0) out vec4 color;
void main() { color = vec4(gl_FragCoord.x < 1.0 ? 0.25 : 0.75); }
