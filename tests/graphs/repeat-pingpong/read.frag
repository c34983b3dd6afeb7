#version 450
layout(location = 0) out vec4 color;
uniform sampler2DArray arr;
void main() { color = texture(arr, vec3(0.5, 0.5, floor(gl_FragCoord.x))); }
