#version 450
// A G-buffer for the NPR presets: mesh placed at OFFSET (TILT: turned 60 degrees about x so a
// ring shows its hole), view-space normal and view depth to the fragment shader. VISIBLE, an
// expression, hides the mesh when false (every vertex outside the clip volume: nothing drawn),
// so a preset can switch draws with a param.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 v_normal;
layout(location = 1) out float v_depth;

#ifndef OFFSET
#define OFFSET vec3(0.0)
#endif

void main() {
#ifdef TILT
    const float c = 0.5, s = 0.8660254;  // cos, sin 60 degrees
    mat3 m = mat3(1, 0, 0, 0, c, s, 0, -s, c);
#else
    mat3 m = mat3(1.0);
#endif
    vec3 world = m * position + OFFSET;
    vec4 view = frame.view * vec4(world, 1.0);
    v_normal = mat3(frame.view) * (m * normal);  // view is rigid: its 3x3 rotates normals
    v_depth = -view.z;
    gl_Position = frame.proj * view;
#ifdef VISIBLE
    if (!(VISIBLE)) gl_Position = vec4(0.0, 0.0, -2.0, 1.0);
#endif
}
