#version 450
layout(location = 0) out vec4 color;
uniform samplerCube env;
void main() {
    const vec3 dirs[6] = vec3[](vec3(1, 0, 0), vec3(-1, 0, 0), vec3(0, 1, 0), vec3(0, -1, 0), vec3(0, 0, 1), vec3(0, 0, -1));
    color = texture(env, dirs[int(gl_FragCoord.x)]);
}
