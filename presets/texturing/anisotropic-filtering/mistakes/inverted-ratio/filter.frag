#version 450
// Three filters of the same texture on a plane seen at a grazing angle
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
    float p_max = max(lx, ly), p_min = max(min(lx, ly), 1e-6);
    vec2 major = (lx >= ly ? dtdx : dtdy);                // in texture coordinates
    float n = clamp(ceil(p_min / p_max), 1.0, float(max_taps));  // MISTAKE: minor / major
    if (!(n >= 1.0)) n = 1.0;  // NaN/Inf derivatives where a quad straddles the horizon
    float lod = log2(max(p_max / n, 1e-6));
    vec4 sum = vec4(0.0);
    for (int i = 0; i < max_taps && float(i) < n; ++i)   // bounded by max_taps whatever n is
        sum += textureLod(s, t + ((float(i) + 0.5) / n - 0.5) * major, lod);
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
