#version 450
// The cube map in ONE pass (000_c9f7e5de708ecbb3.txt L214-217 "Cube Map: GS instances every
// triangle 6x"; 004_9a40ad89bdfc582a.txt L882-886 "render to cube map in a single pass: treat
// cube map as 6-element array, emit primitive multiple times"). The target is attached with
// layer = "all"; geometry-shader instance f (invocations = 6) re-projects the triangle with face
// f's camera and sends it to layer gl_Layer = f. The clip position is the same function of the
// same world position as in the six-pass version, so the two give identical texels.
#include "scene.glsl"
#include "envmap/cube_face_camera.glsl"
layout(triangles, invocations = 6) in;
layout(triangle_strip, max_vertices = 3) out;
layout(location = 0) in vec3 v_world[];
layout(location = 1) in vec3 v_normal[];
layout(location = 2) flat in int v_instance[];
layout(location = 0) out vec3 g_world;
layout(location = 1) out vec3 g_normal;
layout(location = 2) flat out int g_instance;
void main() {
    if (!(ACTIVE) || !scene_visible(v_instance[0])) return;
    int face = gl_InvocationID;
    for (int k = 0; k < 3; ++k) {
        gl_Position = cube_face_clip(face, v_world[k] - kCubeCentre, kCubeNear, kCubeFar);
        gl_Layer = face;
        g_world = v_world[k];
        g_normal = v_normal[k];
        g_instance = v_instance[k];
        EmitVertex();
    }
    EndPrimitive();
}
