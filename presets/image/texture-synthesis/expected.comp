#version 450
// The exact continuation of the periodic source (source = periodic): the seed copies the source
// around kSeedAt to the centre, so texel p must be the tile at p - centre + kSeedAt.
#include "synth_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba8) uniform writeonly image2D expected;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(expected);
    if (any(greaterThanEqual(p, size))) return;
    // + 5 * size keeps the argument of % non-negative
    imageStore(expected, p, vec4(periodic_tile(p - synth_centre(size) + kSeedAt + 5 * size), 1.0));
}
