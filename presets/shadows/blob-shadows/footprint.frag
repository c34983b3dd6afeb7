#version 450
// Test-only: where the blobs should be, from each pixel's world point (shade.frag's `world`):
// r = 1 on ground pixels at least kRim inside a disc, g = 1 on ground pixels at least kRim
// outside every disc; the rim (~1.5 px at the default view) is left out, where the lifted disc's
// edge and the analytic circle may round to different pixels.
#include "blob.glsl"
uniform sampler2D world;
layout(location = 0) out vec4 footprint;
const float kRim = 0.03;
void main() {
    vec4 w = texelFetch(world, ivec2(gl_FragCoord.xy), 0);
    footprint = vec4(0.0);
    if (int(w.w + 0.5) != SHADOW_GROUND + 1) return;
    bool inside = false, outside = true;
    for (int i = 0; i < kBlobs; ++i) {
        float d = distance(w.xz, blob_hit(i).xz), r = blob_radius(i);
        inside = inside || d < r - kRim;
        outside = outside && d > r + kRim;
    }
    footprint = vec4(inside ? 1.0 : 0.0, outside ? 1.0 : 0.0, 0.0, 1.0);
}
