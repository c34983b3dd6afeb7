#version 450
// Reads both cube images along the axes and three off-axis directions.
layout(location = 0) out vec4 dirs;
layout(location = 1) out vec4 ball_dirs;
uniform samplerCube env;
uniform samplerCube ball_env;
void main() {
    const vec3 q[9] = vec3[](vec3(1, 0, 0), vec3(-1, 0, 0), vec3(0, 1, 0), vec3(0, -1, 0), vec3(0, 0, 1), vec3(0, 0, -1),
                             vec3(1, 0.5, 0.25), vec3(-0.25, -0.5, 1), vec3(0.3, -1, 0.6));
    vec3 d = q[int(gl_FragCoord.x)];
    dirs = texture(env, d);
    ball_dirs = texture(ball_env, d);
}
