#version 450
// The ray stage: for every mirror pixel where SSR missed (ALL = 1: every mirror pixel, a test
// that rays and SSR agree where both see), the reflected ray R = reflect(V, N) from the depth
// buffer's point, traced through the BVH (raytrace/hybrid.glsl).
layout(local_size_x = 8, local_size_y = 8) in;
#include "raytrace/hybrid.glsl"
uniform sampler2D gbuf;   // xyz world normal, w reflection map
uniform sampler2D depth;
uniform sampler2D ssr;    // rgb reflected colour, a: SSR hit
layout(rgba16f) writeonly uniform image2D rays;  // rgb reflected colour, a: ray hit

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy), size = imageSize(rays);
    if (any(greaterThanEqual(p, size))) return;
    // ssr_resolution = half: rays (and ssr) are half the view, one ray per 2x2 block from its
    // even pixel of the full-resolution G-buffer and depth, as passes/envmap/ssr.frag does.
    ivec2 q = params.ssr_resolution == SSR_RESOLUTION_HALF ? p * 2 : p;
    vec4 g = texelFetch(gbuf, q, 0);
    vec4 result = vec4(0.0);
    if (g.w > 0.0 && (ALL == 1 || texelFetch(ssr, p, 0).a == 0.0)) {
        vec2 uv = (vec2(q) + 0.5) / vec2(textureSize(depth, 0));
        vec4 w = frame.inv_view_proj * vec4(uv * 2.0 - 1.0, texelFetch(depth, q, 0).r, 1.0);
        vec3 P = w.xyz / w.w, N = normalize(g.xyz);
        vec3 R = reflect(normalize(P - frame.camera_pos.xyz), N);
        result = hybrid_trace_reflection(P, N, R, params.specular);
    }
    imageStore(rays, p, result);
}
