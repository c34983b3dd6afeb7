#version 450
// Draw slot gl_InstanceIndex of the sorted order buffer (sort.comp): the shared scene's quad
// order.object[slot], so the instances reach the over blend farthest first.
#include "oit/quad_vertex.glsl"
layout(std430) readonly buffer Order { uint object[]; } order;
void main() { oit_emit_quad(int(order.object[gl_InstanceIndex])); }
