#version 450
// Test-only: the 2-pixel band around the reference's shadow edges, where a 4096^2 map and an
// exact shadow ray may disagree by a pixel: band.r = 1 where some pixel within 2 px (5 x 5
// neighbourhood) has a different reference visibility.
layout(local_size_x = 8, local_size_y = 8) in;
uniform sampler2D ref_in;
layout(rgba8) writeonly uniform image2D band;
void main() {
    ivec2 px = ivec2(gl_GlobalInvocationID.xy), size = textureSize(ref_in, 0);
    if (any(greaterThanEqual(px, size))) return;
    float c = texelFetch(ref_in, px, 0).r;
    bool edge = false;
    for (int y = -2; y <= 2; ++y)
        for (int x = -2; x <= 2; ++x) edge = edge || texelFetch(ref_in, clamp(px + ivec2(x, y), ivec2(0), size - 1), 0).r != c;
    imageStore(band, px, vec4(edge ? 1.0 : 0.0, 0.0, 0.0, 1.0));
}
