// Tone mapping operators shared by the post presets.
#ifndef PASSLAB_TONEMAP_GLSL
#define PASSLAB_TONEMAP_GLSL
#include "common/color.glsl"  // luminance()

// Jim Hejl's filmic curve as printed in 002_644d46bdce7e5305.txt L641-646 (Hejl/Burgess-Dawson):
//   x = max(0, c - 0.004);  y = x (6.2 x + 0.5) / (x (6.2 x + 1.7) + 0.06)
// Its output is display-encoded already (it contains the 1/2.2 gamma, 002 L656): write it to a
// UNORM target, never through another pow(1/2.2) or an sRGB target.
vec3 tonemap_hejl(vec3 c) {
    vec3 x = max(vec3(0.0), c - 0.004);
    return (x * (6.2 * x + 0.5)) / max(x * (6.2 * x + 1.7) + 0.06, vec3(1e-8));
}

// Reinhard's global operator, L / (1 + L) per channel (linear: encode afterwards).
vec3 tonemap_reinhard(vec3 c) { return c / (1.0 + c); }

// 002 uses autokey() without defining it (L650). Ours: Krawczyk, Myszkowski and Seidel 2005,
// key = 1.03 - 2 / (2 + log10(L + 1)) with L in cd/m^2: darker scenes get a lower key, so night
// stays night. Our radiances are relative; we take 1.0 = 1000 cd/m^2 (a sunlit surface), so a
// scene averaging 0.5 gets key 0.60 and one averaging 0.001 (moonlight) key 0.16.
const float kCandelaPerUnit = 1000.0;
float autokey(float mean_luminance) { return 1.03 - 2.0 / (2.0 + log(kCandelaPerUnit * mean_luminance + 1.0) / log(10.0)); }
#endif
