#version 450
// 0.25 .. 0.75 across the view: any small change of the constants stays inside [0, 1].
layout(location = 0) out vec4 color;
void main() {
    color = vec4(vec3(0.25 + 0.5 * gl_FragCoord.x / frame.resolution.x), 1.0);
}
