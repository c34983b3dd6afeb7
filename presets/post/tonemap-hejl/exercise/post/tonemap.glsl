// EXERCISE — this file shadows passes/post/tonemap.glsl for post/tonemap-hejl only. As shipped
// both curves are a plain clamp; fill in the two TODO blocks.
//     passlab run   post/tonemap-hejl --exercise presets/post/tonemap-hejl/exercise
//     passlab grade post/tonemap-hejl --exercise presets/post/tonemap-hejl/exercise
// Tone mapping operators shared by the post presets.
#ifndef PASSLAB_TONEMAP_GLSL
#define PASSLAB_TONEMAP_GLSL
#include "common/color.glsl"  // luminance()

// Jim Hejl's filmic curve (Hejl / Burgess-Dawson), as printed in 002_644d46bdce7e5305.txt
// L642-646 (function hejl). Its output is display-encoded already: "you don't need the
// pow(color.rgb, vec3(1.0 / 2.2)) for this one" (002 L656), and tonemap.frag writes it to a
// UNORM target as it is.
vec3 tonemap_hejl(vec3 c) {
    // TODO 1: x = max(0, c - 0.004), then y = x (6.2 x + 0.5) / (x (6.2 x + 1.7) + 0.06), per
    // channel, with the listing's max(..., 1e-8) guard on the denominator. Add no gamma.
    return clamp(c, 0.0, 1.0);
}

// Reinhard's global operator, per channel (linear: tonemap.frag encodes it with pow(1/2.2)).
vec3 tonemap_reinhard(vec3 c) {
    // TODO 2: L / (1 + L): 0 stays 0, 1 becomes 1/2, and no radiance ever reaches 1.
    return clamp(c, 0.0, 1.0);
}

// 002 uses autokey() without defining it (L650). Ours: Krawczyk, Myszkowski and Seidel 2005,
// key = 1.03 - 2 / (2 + log10(L + 1)) with L in cd/m^2: darker scenes get a lower key, so night
// stays night. Our radiances are relative; we take 1.0 = 1000 cd/m^2 (a sunlit surface), so a
// scene averaging 0.5 gets key 0.60 and one averaging 0.001 (moonlight) key 0.16.
const float kCandelaPerUnit = 1000.0;
float autokey(float mean_luminance) { return 1.03 - 2.0 / (2.0 + log(kCandelaPerUnit * mean_luminance + 1.0) / log(10.0)); }
#endif
