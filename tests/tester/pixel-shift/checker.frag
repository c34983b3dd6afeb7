#version 450
layout(location = 0) out vec4 color;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy) + ivec2(params.shift, 0);
    color = vec4(vec3(float(((p.x / 2) + (p.y / 2)) & 1)), 1.0);
}
