#version 450
// Stage 0, the raw ray-traced output (000 L5806-5810): a quarter of the pixels trace one sample
// per frame (000 L5790-5791: "25% ray/pixel"; a rotating 2x2 pattern), the others are holes
// (a = 0). Sky pixels trace no ray: their value is the sky's every frame (rgb = sky, a = 0: a
// marks traced samples only, so a test can measure the noise of the traced ones).
// signal = constant replaces every value by 0.5: the invariant that each stage keeps it.
// One invocation per 2x2 block, so that every SIMD lane traces (one thread per pixel would
// leave three lanes of four idle while the fourth traverses the BVH).
layout(local_size_x = 8, local_size_y = 8) in;
#include "scene.glsl"
uniform sampler2D g_position;
uniform sampler2D g_normal;
layout(rgba16f) writeonly uniform image2D raw;

void main() {
    ivec2 block = ivec2(gl_GlobalInvocationID.xy), size = imageSize(raw);
    int chosen = int(frame.index % 4u);
    bool every = params.sampling == SAMPLING_EVERY;
    // The pixels that trace: all four of the block (sampling = every), or the chosen one. A loop
    // over exactly those, not over all four with a per-pixel test: llvmpipe runs a fixed
    // four-pass loop unrolled, each copy's trace (masked) whether its pixel samples or not.
    for (int k = every ? 0 : chosen; k < (every ? 4 : chosen + 1); ++k) {
        ivec2 p = 2 * block + ivec2(k & 1, k >> 1);
        if (any(greaterThanEqual(p, size))) continue;
        vec4 pos = texelFetch(g_position, p, 0);
        vec4 gn = texelFetch(g_normal, p, 0);
        bool sampled = pos.w > 0.0;
        vec3 c = vec3(0.0);
        if (pos.w == 0.0) c = kSky;
        else c = scene_sample(pos.xyz, gn.xyz, albedo_of(gn.w), scene_random(p, frame.index, 0u));
        if (params.signal == SIGNAL_CONSTANT) c = vec3(0.5);
        imageStore(raw, p, vec4(c, sampled ? 1.0 : 0.0));
    }
    if (every) return;
    // The other three: holes (a = 0), or the sky's value.
    for (int k = 0; k < 4; ++k) {
        ivec2 p = 2 * block + ivec2(k & 1, k >> 1);
        if (k == chosen || any(greaterThanEqual(p, size))) continue;
        bool sky = texelFetch(g_position, p, 0).w == 0.0;
        vec3 c = sky ? kSky : vec3(0.0);
        if (params.signal == SIGNAL_CONSTANT && sky) c = vec3(0.5);
        imageStore(raw, p, vec4(c, 0.0));
    }
}
