#version 450
// EXERCISE (TODO 1-3, in texture_aniso). Three filters of the same texture on a plane seen at a grazing angle
// (000_c9f7e5de708ecbb3.txt L1887-1936).
//
// One pixel's footprint in texture space is (close to) a parallelogram spanned by
//     dx = dT/dx * size,   dy = dT/dy * size          (in texels)
// Mipmapping picks one level for it, lod = log2(max(|dx|, |dy|)): a square filter the size of
// the LONGER side, so at grazing angles it "blurs in every direction equally" (L1889-1891).
// Anisotropic filtering (L1930-1934): "determine the major line of anisotropy (= longer axis);
// a fixed number of samples along the line of anisotropy; trilinear interpolation for each
// sample":
//     N   = min(ceil(Pmax / Pmin), max_taps)       taps along the major axis
//     lod = log2(Pmax / N)                          each tap covers 1/N of the major axis
//     T   = 1/N sum_i trilinear(t + ((i + 0.5)/N - 0.5) * major, lod)
// (the same N and lod as the hardware rule of EXT_texture_filter_anisotropic). The slide says
// a FIXED number of samples (L1933); this N adapts to the footprint's aspect up to max_taps
// (a fixed N = max_taps everywhere is README exercise 3), stated, not silently changed.
// The hardware path is lavapipe's (Mesa 22.3): an elliptical weighted average (Heckbert) over
// the texels of the ellipse, not N taps; it derives the ellipse from the quad's own coordinate
// differences even under textureGrad, so the plane is drawn as a mesh (smooth helper lanes).
// One filter per pass (FILTER, a define: SHOW_TRILINEAR, SHOW_HARDWARE or SHOW_SHADER), each pass
// writing its own image; ground.vert clips the plane to the strip that shows the filter.
layout(location = 0) in vec2 v_t;
layout(location = 0) out vec4 result;
#if FILTER == SHOW_SHADER
uniform sampler2D tex_trilinear;   // N trilinear taps along the major axis
#elif FILTER == SHOW_HARDWARE
uniform sampler2D tex_aniso16;     // hardware trilinear + anisotropy 16
#else
uniform sampler2D tex_trilinear;   // hardware trilinear, anisotropy off
#endif

vec4 texture_aniso(sampler2D s, vec2 t, vec2 dtdx, vec2 dtdy, int max_taps) {
    vec2 size = vec2(textureSize(s, 0));
    vec2 ax = dtdx * size, ay = dtdy * size;              // footprint axes in texels
    float lx = length(ax), ly = length(ay);
    // TODO 1: the footprint's major and minor axes (L1930-1931, "determine the major line of
    // anisotropy (= longer axis)"). p_max is the longer of the two axis lengths in texels, p_min
    // the shorter (kept above 1e-6), and `major` the longer axis itself in texture coordinates
    // (dtdx or dtdy): the line the taps are spread along.
    float p_max = 1.0, p_min = 1.0;  // replace
    vec2 major = vec2(0.0);          // replace
    // TODO 2: the number of taps and their level (L1932-1934; the hardware rule of
    // EXT_texture_filter_anisotropic). N is the footprint's aspect, how many minor-axis widths fit
    // along the major axis, rounded up and kept within [1, max_taps]; each tap then covers 1/N
    // of the major axis, so its level is log2 of that length (never below 1e-6):
    //   N = min(ceil(Pmax / Pmin), max_taps),   lod = log2(Pmax / N).
    float n = 1.0;    // replace
    if (!(n >= 1.0)) n = 1.0;  // NaN/Inf derivatives where a quad straddles the horizon
    float lod = 0.0;  // replace
    vec4 sum = vec4(0.0);
    for (int i = 0; i < max_taps && float(i) < n; ++i) {  // bounded by max_taps whatever n is
        // TODO 3: tap i of N (L1933-1934, "samples along the line of anisotropy; trilinear
        // interpolation for each sample"): a trilinear read (textureLod at lod) at the centre of
        // the i-th of N equal pieces of the major axis, the axis centred on t:
        //   t_i = t + ((i + 1/2) / N - 1/2) major.
        sum += textureLod(s, t, lod);  // replace
    }
    return sum / n;
}

void main() {
    // Every fragment that reaches here needs this pass's filter: with params.analysis off the
    // plane is clipped to the filter's strip (ground.vert, strips.glsl), so the filter runs
    // only where it is shown (on lavapipe an untaken branch still costs its full price).
#if FILTER == SHOW_SHADER
    result = vec4(texture_aniso(tex_trilinear, v_t, dFdx(v_t), dFdy(v_t), params.max_taps).rgb, 1.0);
#elif FILTER == SHOW_HARDWARE
    result = vec4(texture(tex_aniso16, v_t).rgb, 1.0);
#else
    result = vec4(texture(tex_trilinear, v_t).rgb, 1.0);
#endif
}
