#version 450
// Test-only: each blob's centroid on screen against the projection of its hit point H
// (docs/catalogue.md 3.11: "blob centred on the hit point +- 1 px"). Run 0 (groups over the view)
// sums the pixels whose blob_id is i + 1; run 1 (one thread) divides and projects the hit point
// as expected_hit() finds it. The test views
// the ground from straight above, where the disc's image is a disc around H's image.
// stats: [0..1] sum x, [2..3] sum y, [4..5] count (uint); [8..9] error in px, [10..11] count (float).
layout(local_size_x = 8, local_size_y = 8) in;
#include "blob.glsl"
#include "shadows/light.glsl"

// The hit point again, by another road (similar triangles on y = 0 with the shared light.glsl's
// direction), so a wrong blob_hit() cannot move the expectation with the blob.
vec3 expected_hit(int i) {
    vec3 c = blob_centre(i), l = shadow_light_dir(c);
    return c - l * (c.y / l.y);
}
uniform sampler2D blob_id;
layout(std430) buffer stats { uint sums[8]; float result[4]; };
void main() {
    if (pl_iteration == 0) {
        ivec2 px = ivec2(gl_GlobalInvocationID.xy);
        if (any(greaterThanEqual(px, textureSize(blob_id, 0)))) return;
        int i = int(texelFetch(blob_id, px, 0).r * 255.0 + 0.5) - 1;
        if (i < 0 || i >= kBlobs) return;
        atomicAdd(sums[i], uint(px.x));
        atomicAdd(sums[2 + i], uint(px.y));
        atomicAdd(sums[4 + i], 1u);
        return;
    }
    if (gl_GlobalInvocationID != uvec3(0)) return;
    vec2 size = vec2(textureSize(blob_id, 0));
    for (int i = 0; i < kBlobs; ++i) {
        float n = float(sums[4 + i]);
        vec2 mean_px = vec2(float(sums[i]), float(sums[2 + i])) / max(n, 1.0) + 0.5;   // pixel centres
        vec4 c = frame.view_proj * vec4(expected_hit(i), 1.0);
        vec2 expected = (c.xy / c.w * 0.5 + 0.5) * size;
        result[i] = n > 0.0 ? distance(mean_px, expected) : 1e9;
        result[2 + i] = n;
    }
}
