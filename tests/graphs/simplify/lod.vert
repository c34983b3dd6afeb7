#version 450
// A mesh (any LOD) from the view camera; object space is world space.
#include "visibility/lod_emit.glsl"
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec2 uv;
void main() { emit(position, normal, uv); }
