#version 450
// Test-only: continuity of the visibility across the cube's face seams (TECHNIQUES.md 3.11:
// "visibility along face seams differs < 0.02 from neighbours"). A receiver pixel is on a seam
// when the two largest |components| of d = p - light differ by less than SEAM_WIDTH of the
// largest (the direction is within ~SEAM_WIDTH radians of the edge between two faces). There,
// r = the largest |vis - vis(neighbour)| over the 4 neighbours 2 px away that are receivers
// too, g = 1 (seam pixel). Pixels in the ray-traced reference's edge band (a real shadow edge
// nearby, ref.b) are left out: a shadow boundary that crosses a seam is not a seam artefact.
#include "shadows/scene.glsl"
uniform sampler2D vis;
uniform sampler2D world;
uniform sampler2D ref;
layout(location = 0) out vec4 seam;

bool receiver(ivec2 q) { return int(texelFetch(world, q, 0).w + 0.5) == SHADOW_GROUND + 1; }

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy), size = textureSize(vis, 0);
    seam = vec4(0.0);
    if (!receiver(px) || texelFetch(ref, px, 0).b > 0.5) return;
    vec3 a = abs(texelFetch(world, px, 0).xyz - SEAM_LIGHT);
    float hi = max(a.x, max(a.y, a.z)), lo = min(a.x, min(a.y, a.z)), mid = a.x + a.y + a.z - hi - lo;
    if (hi - mid >= SEAM_WIDTH * hi) return;
    float v = texelFetch(vis, px, 0).r, worst = 0.0;
    const ivec2 kStep[4] = ivec2[](ivec2(2, 0), ivec2(-2, 0), ivec2(0, 2), ivec2(0, -2));
    for (int k = 0; k < 4; ++k) {
        ivec2 q = px + kStep[k];
        if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size)) || !receiver(q)) continue;
        worst = max(worst, abs(texelFetch(vis, q, 0).r - v));
    }
    seam = vec4(worst, 1.0, 0.0, 1.0);
}
