#version 450
// The shifted-copy test (scene = shift, A(p) = B(p + d)): r = 1 where f(a) - a == d exactly,
// g = 1 on the interior, the patches whose exact match a + d is a valid centre of B
// (the whole patch of a and of a + d inside the images); the check counts r over g.
#include "image/nnf.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
uniform sampler2D nnf_in;
layout(rgba8) uniform writeonly image2D shift_ok;

void main() {
    ivec2 a = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = textureSize(nnf_in, 0);
    if (any(greaterThanEqual(a, size))) return;
    int r = params.patch_radius;
    ivec2 b = a + ivec2(params.shift);
    bool interior = all(greaterThanEqual(min(a, b), ivec2(r))) && all(lessThan(max(a, b), size - r));
    bool exact = nnf_target(texelFetch(nnf_in, a, 0)) - a == ivec2(params.shift);
    imageStore(shift_ok, a, vec4(exact ? 1.0 : 0.0, interior ? 1.0 : 0.0, 0.0, 1.0));
}
