#version 450
// A cube map unfolded into a horizontal cross, 4 x 3 cells of one face each:
//            +Y
//       -X   +Z   +X   -Z
//            -Y
// With cube.glsl's face orientation every shared edge of the cross is a shared edge of the cube
// (e.g. the right border of +Z, direction (1, -t, 1), is the left border of +X), so a correct
// map shows no break across the inner edges. Texel centres of the cross hit texel centres of
// the faces when the cross is 4n x 3n for n x n faces (sample with a nearest sampler to copy
// texels exactly; at texel centres a linear sampler returns the texel too). Empty cells are EMPTY
// (default black).
#include "envmap/cube.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 unfolded;
uniform samplerCube env;
#ifndef EMPTY
#define EMPTY vec4(0.0)
#endif
void main() {
    vec2 g = uv * vec2(4.0, 3.0);
    ivec2 cell = ivec2(min(floor(g), vec2(3.0, 2.0)));
    // cells (column, row) -> face index (+X 0, -X 1, +Y 2, -Y 3, +Z 4, -Z 5), -1 = empty
    const int kFace[12] = int[](-1, 2, -1, -1, 1, 4, 0, 5, -1, 3, -1, -1);
    int face = kFace[cell.y * 4 + cell.x];
    unfolded = face < 0 ? EMPTY : vec4(textureLod(env, cube_face_direction(face, fract(g)), 0.0).rgb, 1.0);
}
