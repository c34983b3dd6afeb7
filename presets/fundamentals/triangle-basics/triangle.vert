#version 450
// The vertex stage's one duty (000_c9f7e5de708ecbb3.txt L53-185): transform each vertex to
// clip space, gl_Position = mvp * vec4(p, 1) (docs/catalogue.md), and pass on its attributes, a
// colour per vertex, which the rasterizer interpolates across the triangle.
// mvp = P * V * M. In this 2D lesson V and P are the identity (object x, y are clip x, y,
// Vulkan's y pointing down), and M rotates about z by params.angle: a transform that moves the
// triangle and carries the interpolated colours with it.
layout(location = 0) out vec3 v_color;
void main() {
    const vec2 p[3] = vec2[](vec2(-0.8, 0.8), vec2(0.8, 0.8), vec2(0.0, -0.8));
    const vec3 c[3] = vec3[](vec3(1, 0, 0), vec3(0, 1, 0), vec3(0, 0, 1));
    float a = radians(params.angle);
    mat4 model = mat4(cos(a), sin(a), 0, 0,  -sin(a), cos(a), 0, 0,  0, 0, 1, 0,  0, 0, 0, 1);
    mat4 view = mat4(1.0), proj = mat4(1.0);
    gl_Position = proj * view * model * vec4(p[gl_VertexIndex], 0.0, 1.0);
    v_color = c[gl_VertexIndex];
}
