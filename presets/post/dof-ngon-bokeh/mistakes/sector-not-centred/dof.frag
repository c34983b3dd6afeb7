#version 450
// EXERCISE — TODO 3 (TODO 1, 2 in bokeh_taps.glsl).
// The 64k intro's depth of field (002_644d46bdce7e5305.txt L1497-1560), one gather pass:
//   fstop (002: max(1, uFStop * 64)), CoC = 0.03 mm, threshold 0.5, gain 2.0, fringe 0.7
//   f = 35 mm; d = the focal plane (002: the depth at the screen centre, autofocus), o = this
//   pixel's depth, both in mm (002 reads metres from the depth texture's w and x 1000)
//   blur = |f^2 (d - o) / ((d - f)(o - f))| (d - f) / (d fstop CoC)   (pixels; post/coc.glsl)
// If the blur is more than 0.0005 of the view (length in uv), gather a (si + 1)^2 grid of taps,
// si = ceil(clamp(3 blur, 2, clamp(maxTaps, 2, 16))), shaped by getBokehTapSampleCoord and
// scaled by blur pixels; each tap's weight b = 1 + col max((luma(col) - threshold) gain, 0) blur
// lifts highlights (bright taps count more: the bokeh discs light up); the pixel itself counts 1.
// Optional chromatic aberration fetches r, g, b fringe x blur pixels apart (params.chromatic in
// percent: 002's uChromaticAberration x 100).
// PITFALLS of the printed code (fixed, stated): the sampler is declared `fboColotBuffer` and
// used as `fboColorBuffer` (here one name, `color`); `bias = 0.5` is declared and never used
// (dropped); GLSL 1.50 `varying` / `gl_FragColor` become in / out.
// RESOLUTION (not 002's; for a live frame rate on a CPU rasteriser): `full` gathers per view
// pixel from the full-resolution colour, as printed; `half` gathers per 2x2 pixels (this pass's
// targets are view/2) from the colour's mip 1 (the 2x2 box mean, so a tap sees everything the
// half-res pixel covers). The blur stays in view pixels for the weights and the offsets; the
// tap count follows the blur in *gather* pixels, si = ceil(clamp(3 blur / scale, ...)), so the
// taps keep 002's spacing of about a third of a gather pixel. display.frag composites the
// upsampled half-res result with the sharp full-res colour where the blur is under 2 px.
// Also writes `blur` = (the simplified blur, the unsimplified |a - b| c of 002's comment L1532,
// |difference|, how much the gather changed the pixel (largest channel)) for the tests.
#include "post/coc.glsl"
#ifndef CHROMATIC
#define CHROMATIC 1  // the fringe taps (preset.toml: off in the pass `dof`)
#endif
layout(location = 0) in vec2 vTexCoord;
layout(location = 0) out vec4 result;
layout(location = 1) out vec4 blur_out;
uniform sampler2D color;
uniform sampler2D depth;
uniform sampler2D tap_table;
const float CoC = 0.03;  // circle of confusion size in mm (35mm film = 0.03mm)
const float threshold = 0.5, gain = 2.0, fringe = 0.7;  // highlight threshold and gain, bokeh fringe
// mip 0 (full) or mip 1 (half: the 2x2 box mean, from the mips pass)
vec4 sampleIt(vec2 coords) { return max(vec4(0.0), textureLod(color, coords, float(params.resolution == RESOLUTION_HALF))); }
void main() {
    float fstop = params.fstop;
    float chromatic = float(params.chromatic) / 100.0;  // 002's uChromaticAberration (0..1)
    float f = params.focal_length;  // focal length in mm (002: 35)
    float d = (params.focus_mode == FOCUS_MODE_CENTRE ? texture(depth, vec2(0.5)).x : params.focus) * 1000.0;
    // full: this pixel's depth texel; half: one texel of the 2x2 it covers (no depth average
    // across silhouettes: the blur of a real surface).
    ivec2 px = params.resolution == RESOLUTION_FULL ? ivec2(gl_FragCoord.xy) : 2 * ivec2(gl_FragCoord.xy);
    float o = texelFetch(depth, px, 0).x * 1000.0;  // depth in mm
    float blur = blur_64k(f, d, o, fstop, CoC);
    float a = (o * f) / (o - f), b = (d * f) / (d - f), c_ = (d - f) / (d * fstop * CoC), blur_long = abs(a - b) * c_;
    vec4 c = sampleIt(vTexCoord), c0 = c;
    vec2 uCanvasInvSize = vec2(1.0) / vec2(textureSize(color, 0).xy);  // view pixels (mip 0)
    vec2 wh = uCanvasInvSize * blur;
    float scale = params.resolution == RESOLUTION_FULL ? 1.0 : 2.0;  // view pixels per gather pixel
    if (length(wh) > 0.0005) {
        // TODO 3 (L1539-1556): s is the sum of the weights; the pixel itself (already in c) counts 1.
        vec3 s = vec3(1.0);
        vec2 si = vec2(ceil(clamp(blur / scale * 3.0, 2.0, clamp(float(params.max_taps), 2.0, 16.0)))), sio = si + vec2(1.0);
        // The (si + 1)^2 taps in 002's order (sy outer, sx inner) as one loop over the table's
        // index i = sy (si + 1) + sx: the same taps summed in the same order (the same result),
        // one integer counter instead of two nested float loops (speed, lavapipe).
        int row = int(si.x) - 2, n = int(sio.x * sio.y);
        vec2 t = uCanvasInvSize * fringe * blur;
        for (int i = 0; i < n; ++i) {
            // getBokehTapSampleCoord(vec2(sx, sy) / si, ...), from the baked table (tap_table.frag).
            vec2 pwh = texelFetch(tap_table, ivec2(i, row), 0).xy;
            vec2 coords = vTexCoord + (pwh * wh);
            vec3 col = sampleIt(coords).xyz;
#if CHROMATIC
            // Only in the pass dof_chromatic (preset.toml: chromatic > 0): lavapipe fetches the
            // three fringe taps of this branch even where it is not taken, so the pass that runs
            // at chromatic = 0 (dof, CHROMATIC 0) is compiled without it (3x faster).
            if (chromatic > 1e-6) {
                // 002's (0, 1) is up with v up: (0, -1) here; the diagonals likewise.
                col = mix(col, vec3(sampleIt(coords + vec2(0.0, -1.0) * t).x, sampleIt(coords + vec2(-0.866, 0.5) * t).y,
                                    sampleIt(coords + vec2(0.866, 0.5) * t).z), chromatic);
            }
#endif
            vec3 bw = (vec3(1.0) + mix(vec3(0.0), col, max((dot(col, vec3(0.299, 0.587, 0.114)) - threshold) * gain, 0.0) * blur));
            // TODO 3: add this tap, weighted by bw, to c, and its weight to s.
            c.xyz += col * bw;
            s += bw;
        }
        // TODO 3 (continued): the result is the weighted mean of the taps and the pixel.
        c.xyz /= s;
    }
    result = c;
    vec3 change = abs(c.xyz - c0.xyz);
    blur_out = vec4(blur, blur_long, abs(blur - blur_long), max(change.x, max(change.y, change.z)));
}
