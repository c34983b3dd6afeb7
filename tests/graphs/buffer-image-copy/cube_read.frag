#version 450
// Pixel k looks along the axis of cube face k (+X, -X, +Y, -Y, +Z, -Z) through the alias.
layout(location = 0) out vec4 color;
uniform samplerCube sky_nearest;
const vec3 kAxis[6] = vec3[](vec3(1, 0, 0), vec3(-1, 0, 0), vec3(0, 1, 0), vec3(0, -1, 0), vec3(0, 0, 1), vec3(0, 0, -1));
void main() { color = texture(sky_nearest, kAxis[int(gl_FragCoord.x)]); }
