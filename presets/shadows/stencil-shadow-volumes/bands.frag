#version 450
// Test-only: the 2-pixel edge band where the stencil result and the shadow map may legitimately
// differ (docs/catalogue.md 3.11: ">= 99% agreement outside 2-px edge bands"). A pixel is in the band
// when, within 2 pixels (a 5 x 5 block), either visibility image changes value: the map's edges
// are a texel off and stair-stepped, the volumes' follow the faceted silhouette exactly.
// The background (world.w == 0, nothing to shadow) is left out too, so the share is taken over
// the surfaces: a wrong ball (3% of them) cannot hide in the sky. r = 1 where not counted.
uniform sampler2D world;
uniform sampler2D smap_vis;
layout(location = 0) out vec4 band;
void main() {
    ivec2 px = ivec2(gl_FragCoord.xy), size = textureSize(smap_vis, 0);
    float b = texelFetch(smap_vis, px, 0).r;
    bool edge = false;
    for (int j = -2; j <= 2; ++j)
        for (int i = -2; i <= 2; ++i) {
            ivec2 q = clamp(px + ivec2(i, j), ivec2(0), size - 1);
            edge = edge || abs(texelFetch(smap_vis, q, 0).r - b) > 0.5;
        }
    bool background = texelFetch(world, px, 0).w == 0.0;
    band = vec4(edge || background ? 1.0 : 0.0);
}
