#version 450
// The uniform environment the sphere sits in: radiance 1 for the white furnace. When lit by
// the light, a dim backdrop (not reflected: Lambert here sees only the light) keeps the dark
// half's silhouette visible against it.
layout(location = 0) out vec4 color;
void main() { color = vec4(vec3(params.mode == MODE_FURNACE ? 1.0 : 0.04), 1.0); }
