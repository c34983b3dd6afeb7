#version 450
// Stage 0, the raw ray-traced output (000 L5806-5810): a quarter of the pixels trace one sample
// per frame (000 L5790-5791: "25% ray/pixel"; a rotating 2x2 pattern), the others are holes
// (a = 0). Sky pixels trace no ray: their value is the sky's every frame (rgb = sky, a = 0: a
// marks traced samples only, so a test can measure the noise of the traced ones).
// signal = constant replaces every sample by 0.5: the invariant that each stage keeps it.
layout(local_size_x = 8, local_size_y = 8) in;
#include "scene.glsl"
uniform sampler2D g_position;
uniform sampler2D g_normal;
layout(rgba16f) writeonly uniform image2D raw;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(raw)))) return;
    vec4 pos = texelFetch(g_position, p, 0);
    vec4 gn = texelFetch(g_normal, p, 0);
    bool sampled = params.sampling == SAMPLING_EVERY || (p.x & 1) + 2 * (p.y & 1) == int(frame.index % 4u);
    vec3 c = vec3(0.0);
    if (pos.w == 0.0) c = kSky;
    else if (sampled) c = scene_sample(pos.xyz, gn.xyz, albedo_of(gn.w), scene_random(p, frame.index, 0u));
    if (params.signal == SIGNAL_CONSTANT) c = vec3(0.5);
    imageStore(raw, p, vec4(pos.w == 0.0 || sampled ? c : vec3(0.0), pos.w > 0.0 && sampled ? 1.0 : 0.0));
}
