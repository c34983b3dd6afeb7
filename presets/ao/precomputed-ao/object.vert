#version 450
// Draws patch gl_InstanceIndex of scene.glsl: a plane mesh's (u, v) moved onto the surface the
// bake sampled. Absent patches (not in the chosen scene) are sent outside the clip volume.
#include "ao/scene.glsl"
layout(location = 2) in vec2 uv;
layout(location = 0) out vec3 v_world;
layout(location = 1) out vec3 v_normal;
layout(location = 2) out vec2 v_atlas;   // where this point's texel lies in the AO atlas
layout(location = 3) flat out int v_id;

void main() {
    int id = gl_InstanceIndex;
    vec3 p, n;
    surface_point(id, uv, p, n);
    // Texel centres sit at (i + 0.5) / tile: clamping keeps bilinear filtering inside the tile.
    float half_texel = 0.5 / float(params.tile);
    v_atlas = (atlas_tile(id) + clamp(uv, half_texel, 1.0 - half_texel)) / 4.0;
    v_world = p;
    v_normal = n;
    v_id = id;
    gl_Position = frame.view_proj * vec4(p, 1.0);
    if (!surface_present(id)) gl_Position = vec4(0.0, 0.0, -2.0, 1.0);
}
