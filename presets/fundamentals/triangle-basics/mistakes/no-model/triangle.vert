#version 450
// EXERCISE — the vertex stage (000_c9f7e5de708ecbb3.txt L53-185): transform each vertex to clip
// space and pass on its attributes, which the rasterizer interpolates across the triangle.
// Fill in the three TODO blocks, then check your work against the reference:
//     passlab run   fundamentals/triangle-basics --exercise presets/fundamentals/triangle-basics/exercise
//     passlab grade fundamentals/triangle-basics --exercise presets/fundamentals/triangle-basics/exercise
// In this 2D lesson V and P are the identity (object x, y are clip x, y; Vulkan's y points down).
layout(location = 0) out vec3 v_color;
void main() {
    const vec2 p[3] = vec2[](vec2(-0.8, 0.8), vec2(0.8, 0.8), vec2(0.0, -0.8));
    const vec3 c[3] = vec3[](vec3(1, 0, 0), vec3(0, 1, 0), vec3(0, 0, 1));
    float a = radians(params.angle);
    // TODO 1: M, the rotation about z by a (counter-clockwise in x, y):
    //     x' = cos(a) x - sin(a) y,   y' = sin(a) x + cos(a) y,   z' = z,   w' = w.
    // GLSL's mat4(...) constructor takes its 16 numbers column by column.
    mat4 model = mat4(cos(a), sin(a), 0, 0,  -sin(a), cos(a), 0, 0,  0, 0, 1, 0,  0, 0, 0, 1);
    mat4 view = mat4(1.0), proj = mat4(1.0);
    // TODO 2: the clip-space position, gl_Position = mvp * vec4(p, 0, 1) with mvp = P * V * M
    // (000 L53-185): which matrix is applied to the point first?
    gl_Position = proj * view * vec4(p[gl_VertexIndex], 0.0, 1.0);
    // TODO 3: hand the rasterizer this vertex's colour (a colour per vertex, red, green, blue),
    // so that every pixel receives the barycentric blend of the three (000 L690-778).
    v_color = c[gl_VertexIndex];
}
