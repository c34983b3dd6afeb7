#version 450
// The source texture (003_cfc3b5b225ddab3d.txt L11-13: "a low resolution texture image"):
// a brick wall (structure to keep: mortar lines, half-brick offsets), or a tile of 5x5 random
// colours repeated (period 5 <= N: synthesis must continue it exactly). 8-bit values.
#include "image/bricks.glsl"
#include "synth_common.glsl"

layout(location = 0) out vec4 color;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    color = vec4(params.source == SOURCE_PERIODIC ? periodic_tile(p) : image_bricks(p, ivec2(12, 6), 3), 1.0);
}
