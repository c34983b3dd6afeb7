#version 450
// PatchMatch idea #1 (003_cfc3b5b225ddab3d.txt L129-133): "a non-trivial fraction of a large
// field of random offset assignments are likely to be good guesses: initialise f with random
// values". On the first frame (frame.accum_frame == 0, also after any param change) every patch
// of A gets a uniformly random valid centre of B; on later frames the field is carried over from
// the previous frame (history), so frame n runs iteration n + 1 on top of it.
#include "common/hash.glsl"
#include "image/patch.glsl"
#include "image/nnf.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
uniform sampler2D A;
uniform sampler2D B;
uniform sampler2D nnf_prev;
layout(rgba32f) uniform writeonly image2D nnf_out;

void main() {
    ivec2 a = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(a, textureSize(A, 0)))) return;
    if (frame.accum_frame > 0) {
        imageStore(nnf_out, a, texelFetch(nnf_prev, a, 0));
        return;
    }
    int r = params.patch_radius;
    ivec2 size_b = textureSize(B, 0);
    vec2 u = vec2(pcg3d(uvec3(a, uint(params.seed) * 7919u)).xy) * (1.0 / 4294967296.0);
    ivec2 b = patch_clamp_centre(ivec2(vec2(r) + u * vec2(size_b - 2 * r)), size_b, r);
    imageStore(nnf_out, a, nnf_encode(b, patch_ssd(A, a, B, b, r, 1e30)));
}
