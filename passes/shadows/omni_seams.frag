#version 450
// Test-only: continuity of a point light's visibility across the seams of its shadow maps
// (docs/catalogue.md 3.11: cube "visibility along face seams differs < 0.02 from neighbours",
// paraboloid "continuous across the seam (< 0.02)"). Seam pixels, for d = p - SEAM_LIGHT:
//   cube (default)          the two largest |components| of d differ by less than SEAM_WIDTH of
//                           the largest (d within ~SEAM_WIDTH radians of an edge between faces);
//   SEAM_PARABOLOID = axis  |d . axis| < SEAM_WIDTH |d| (within ~SEAM_WIDTH radians of the rim
//                           where the two paraboloid discs meet).
// There r = the largest |vis - vis(neighbour)| over the 4 neighbours 2 px away that are
// receivers too and lie within kSameSurface of it, g = 1 (a seam pixel). Pixels in the ray-traced
// reference's edge band (a true shadow edge nearby, ref.b) are left out: a shadow boundary
// crossing a seam is no artefact.
#include "shadows/scene.glsl"
uniform sampler2D vis;
uniform sampler2D world;
uniform sampler2D ref;
layout(location = 0) out vec4 seam;

bool on_seam(vec3 d) {
#ifdef SEAM_PARABOLOID
    return abs(dot(d, SEAM_PARABOLOID)) < SEAM_WIDTH * length(d);
#else
    vec3 a = abs(d);
    float hi = max(a.x, max(a.y, a.z)), lo = min(a.x, min(a.y, a.z)), mid = a.x + a.y + a.z - hi - lo;
    return hi - mid < SEAM_WIDTH * hi;
#endif
}

bool receiver(ivec2 q) { return int(texelFetch(world, q, 0).w + 0.5) == SHADOW_GROUND + 1; }

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy), size = textureSize(vis, 0);
    seam = vec4(0.0);
    if (!receiver(px) || texelFetch(ref, px, 0).b > 0.5) return;
    if (!on_seam(texelFetch(world, px, 0).xyz - SEAM_LIGHT)) return;
    float v = texelFetch(vis, px, 0).r, worst = 0.0;
    const float kSameSurface = 0.1;   // world units; 2 px span ~0.05 on the back wall at 640x360
    const ivec2 kStep[4] = ivec2[](ivec2(2, 0), ivec2(-2, 0), ivec2(0, 2), ivec2(0, -2));
    for (int k = 0; k < 4; ++k) {
        ivec2 q = px + kStep[k];
        if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size)) || !receiver(q)) continue;
        // Only neighbours on the same stretch of surface: across a room corner or onto a wall
        // seen edge-on the neighbour is another receiver with its own light, not the seam.
        if (distance(texelFetch(world, q, 0).xyz, texelFetch(world, px, 0).xyz) > kSameSurface) continue;
        worst = max(worst, abs(texelFetch(vis, q, 0).r - v));
    }
    seam = vec4(worst, 1.0, 0.0, 1.0);
}
