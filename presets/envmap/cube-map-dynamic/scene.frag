#version 450
// Shading of the scene: the sky box shows the environment in the direction from the cube map's
// centre; the boxes are Lambert-lit by the sun with a sky-coloured ambient term.
#include "scene.glsl"
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 2) flat in int v_instance;
layout(location = 0) out vec4 hdr;
const float kAmbient = 0.25;  // fraction of the albedo lit by the sky from every side
void main() {
    if (v_instance == kCubes) { hdr = vec4(scene_environment(v_world), 1.0); return; }
    vec3 n = normalize(v_normal), l = normalize(params.sun_dir);
    hdr = vec4(scene_albedo(v_instance) * (kAmbient + (1.0 - kAmbient) * max(dot(n, l), 0.0)), 1.0);
}
