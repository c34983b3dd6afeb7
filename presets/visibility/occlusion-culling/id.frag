#version 450
// Depth pre-pass of 000_c9f7e5de708ecbb3.txt L6274-6279 ("Pass 1: rasterize the geometry, only
// write depth + object id"): the id of the nearest object per pixel, object + 1 for a box (0 stays
// the clear: background) and PL_VIS_OBJECTS + 1 for the wall, which occludes but is not culled.
#include "visibility/scene.glsl"
layout(location = 0) in vec3 normal;
layout(location = 1) flat in int object;
layout(location = 0) out uint id;
void main() {
    id = object < 0 ? uint(PL_VIS_OBJECTS + 1) : uint(object + 1);
}
