#version 450
// Geomorph (Hoppe 1996): every vertex of the fine LOD slides towards the vertex of the coarse
// LOD it collapses into; at factor 1 the collapsed faces have no area left and the rest are the
// coarse LOD's faces. The lerp is written as a(1-f) + b f, not mix(), whose a + (b-a) f form is
// not exactly b at f = 1.
#include "visibility/lod_emit.glsl"
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec2 uv;
layout(location = 4) in vec3 morph_position;
layout(location = 5) in vec3 morph_normal;
layout(location = 6) in vec2 morph_uv;
#ifndef MORPH
#define MORPH params.morph
#endif
void main() {
    float f = MORPH;
    emit(position * (1.0 - f) + morph_position * f, normal * (1.0 - f) + morph_normal * f, uv * (1.0 - f) + morph_uv * f);
}
