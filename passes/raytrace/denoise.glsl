// Pieces of the real-time denoising pipeline (000_c9f7e5de708ecbb3.txt L5806-5858: raw ray-trace
// output -> spatial reconstruction -> temporal accumulation -> bilateral clean-up -> TAA).
// Every filter here is a normalised weighted mean, sum(w_i x_i) / sum(w_i) with w_i >= 0: a
// constant image stays that constant through every stage (the pipeline's first invariant).
//
// Edge stopping uses the G-buffer, not the noisy colour: a neighbour counts when it lies on the
// same surface as the centre pixel (normals agree, the neighbour's point is near the centre's
// tangent plane). Noise never stops a filter this way; geometry always does.
#ifndef PASSLAB_RAYTRACE_DENOISE_GLSL
#define PASSLAB_RAYTRACE_DENOISE_GLSL

// Weight of a neighbour (point q, normal nq) for the centre (point p, normal n): 1 on the same
// plane, falling with the angle between the normals (cos^8: 0.5 at 24 degrees) and to 0 once q
// is more than plane_tol off the centre's tangent plane. (cos^8 by three squarings: pow() is an
// exp and a log per tap, in a 25-tap loop.)
float denoise_geometry_weight(vec3 p, vec3 n, vec3 q, vec3 nq, float plane_tol) {
    float plane = max(0.0, 1.0 - abs(dot(q - p, n)) / plane_tol);
    float c = max(dot(n, nq), 0.0), c2 = c * c, c4 = c2 * c2;
    return plane * c4 * c4;
}

// Where this pixel's centre was last frame, in uv: the pixel's uv plus the motion of the point it
// sees, from the two frames' unjittered cameras (Vulkan NDC with passlab's y-flipped projection:
// uv = ndc * 0.5 + 0.5, (0, 0) top-left). The sub-pixel jitter is left out on purpose: the
// histories hold values at pixel centres, so a still camera reads its own texel back exactly,
// without the blur a bilinear read at jittered positions would add every frame.
vec2 denoise_previous_uv(vec3 p, vec2 pixel_uv, mat4 view_proj, mat4 prev_view_proj) {
    vec4 now = view_proj * vec4(p, 1.0), before = prev_view_proj * vec4(p, 1.0);
    return pixel_uv + (before.xy / before.w - now.xy / now.w) * 0.5;
}

// Whether last frame's surface at the reprojected texel is this one (else: disocclusion, the
// history belongs to another surface and is dropped).
bool denoise_same_surface(vec3 p, vec3 n, vec4 prev_position, vec3 prev_normal, float tol) {
    return prev_position.w > 0.0 && distance(prev_position.xyz, p) < tol && dot(prev_normal, n) > 0.9;
}
#endif
