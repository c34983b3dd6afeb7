#version 450
// One-bounce reference (test-only): per view pixel, the indirect radiance after exactly one
// diffuse bounce, L1(x) = rho_x/pi * Int L0(y) cos dw, estimated by Monte Carlo with params.spp
// cosine-weighted rays (pdf cos/pi, so L1 = rho_x * mean L0(y)); L0(y) = rho_y/pi * E_direct(y) with a
// ray-traced shadow (000_c9f7e5de708ecbb3.txt L4919-5045: the Neumann series' first indirect
// term). The points and normals are the view G-buffer's (`g_pos`, `g_normal`, `g_albedo`), so
// the reference and the method are compared on the same surfaces. Writes `reference` (rgb = L1).
//
// The pass runs repeat = ceil(spp / VPL_REF_CHUNK) times, each iteration VPL_REF_CHUNK more
// samples of the same Hammersley set folded into a running mean: llvmpipe ends loops after 65535
// iterations counted over the whole invocation (gallivm's LP_MAX_TGSI_LOOP_ITERATIONS, "shared
// between every loop": an inner loop's iterations add up across its re-entries), so one
// invocation tracing 1024 samples through the BVH silently stopped after ~500 of them (measured:
// spp 1024 gave half the radiance of spp 512).
layout(local_size_x = 8, local_size_y = 8) in;
#include "gi/vpl_trace.glsl"
uniform sampler2D g_albedo, g_normal, g_pos;
layout(rgba32f) uniform image2D reference;
const int VPL_REF_CHUNK = 128;
void main() {
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(px, imageSize(reference)))) return;
    vec4 pos = texelFetch(g_pos, px, 0);
    if (pos.w == 0.0) { imageStore(reference, px, vec4(0.0)); return; }
    if (pl_iteration * VPL_REF_CHUNK >= params.spp) return;
    vec3 x = pos.xyz, n = normalize(texelFetch(g_normal, px, 0).xyz);
    uint seed = vpl_hash(uint(px.x) * 1973u + uint(px.y) * 9277u + 1u);
    vec2 shift = vec2(vpl_hash(seed), vpl_hash(seed + 1u)) * 2.3283064e-10;  // Cranley-Patterson rotation
    vec3 sum = vec3(0.0);
    int first = pl_iteration * VPL_REF_CHUNK, last = min(first + VPL_REF_CHUNK, params.spp);
    for (int s = first; s < last; ++s) {
        vec2 u = fract(vec2((float(s) + 0.5) / float(params.spp), vpl_radical_inverse(uint(s))) + shift);
        VplSurface y = vpl_trace(x + n * 1e-3, vpl_cosine_direction(n, u), 0.0);
        if (y.hit) sum += y.albedo / 3.14159265 * vpl_direct_irradiance(y.p, y.n);
    }
    vec3 chunk = texelFetch(g_albedo, px, 0).rgb * sum;  // rho_x * the sum of L0 over this chunk
    vec3 before = pl_iteration == 0 ? vec3(0.0) : imageLoad(reference, px).rgb * float(first);
    imageStore(reference, px, vec4((before + chunk) / float(last), 1.0));
}
