#version 450
// Bake step 0: copy each vertex's world position and normal into `verts`, so that the transfer
// bake (a compute pass) can run once per vertex. Drawn with every vertex outside the clip volume:
// nothing is rasterised, only this vertex shader runs (several times per shared vertex, each
// writing the same values). MESH is the mesh index (0 teapot, 1 floor).
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(std430) writeonly buffer Verts { vec4 v[]; } verts;  // 2 per vertex: (world position, 1), (normal, 0)
#include "env.glsl"
void main() {
    if (uint(gl_VertexIndex) < PRT_CAPACITY) {
        uint i = uint(MESH) * PRT_CAPACITY + uint(gl_VertexIndex);
        verts.v[2u * i] = vec4(position + prt_offset(uint(MESH)), 1.0);
        verts.v[2u * i + 1u] = vec4(normalize(normal), 0.0);
    }
    gl_Position = vec4(0.0, 0.0, 2.0, 1.0);  // z > w: clipped
}
