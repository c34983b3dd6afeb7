#version 450
// EXERCISE — per-vertex versus per-pixel lighting: TODO 1-2 here, TODO 3 in light.vert, TODO 4
// in lighting.glsl. As shipped both modes show the vertex colour, and light.vert writes none.
//     passlab run   bump/per-pixel-lighting --exercise presets/bump/per-pixel-lighting/exercise
//     passlab grade bump/per-pixel-lighting --exercise presets/bump/per-pixel-lighting/exercise
// Per pixel (000 L2366-2381, 001_fe43b953f362fae7.txt L400-410): the interpolated normal is
// renormalised and the same Blinn-Phong evaluated for every fragment. Alpha marks coverage.
#include "lighting.glsl"
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 2) in vec3 v_color;
layout(location = 0) out vec4 color;
void main() {
    // TODO 1: the normal for this fragment. "Vertex normals are passed to the fragment shader,
    // the rasterizer interpolates them" (000_c9f7e5de708ecbb3.txt L2377-2379): v_normal is a
    // linear blend of unit vectors across the triangle. Is it still one?
    vec3 n = v_normal;
    // TODO 2: per pixel (000 L2366-2369, 001_fe43b953f362fae7.txt L404-407) the illumination is
    // calculated at each pixel: blinn_phong(n, p) of lighting.glsl, with p this fragment's
    // world position. Per vertex (params.mode == MODE_PER_VERTEX) the colour computed at the
    // vertices is interpolated instead: v_color.
    vec3 c = v_color;
    color = vec4(c, n.z);
}
