#version 450
// Minification (000_c9f7e5de708ecbb3.txt L1778-1885): far away one pixel covers many texels;
// point sampling then aliases into moire. Prefiltering stores 2:1 averages (the mip chain);
// the sampler picks level D = log2(texels per pixel) and, trilinearly, blends the two nearest
// levels: (D1 - D) T0 + (D - D0) T1. show_level colours the level it picks.
layout(location = 0) in vec2 v_uv;
layout(location = 0) out vec4 color;
uniform sampler2D checker_nearest;
uniform sampler2D checker_bilinear;
uniform sampler2D checker_trilinear;
void main() {
    vec3 c;
    if (params.filtering == FILTERING_COMPARE) {
        // Split view, thirds of the screen: nearest | bilinear | trilinear. All three are sampled
        // in uniform control flow (the sampler's derivatives need the whole 2x2 quad), then one
        // is kept; a thin line marks each border.
        vec3 n = texture(checker_nearest, v_uv).rgb, b = texture(checker_bilinear, v_uv).rgb;
        vec3 t = texture(checker_trilinear, v_uv).rgb;
        float x = gl_FragCoord.x / frame.resolution.x;
        c = x < 1.0 / 3.0 ? n : x < 2.0 / 3.0 ? b : t;
        if (abs(x - 1.0 / 3.0) < 0.0015 || abs(x - 2.0 / 3.0) < 0.0015) c = vec3(1.0, 0.8, 0.2);
    } else if (params.filtering == FILTERING_NEAREST) c = texture(checker_nearest, v_uv).rgb;
    else if (params.filtering == FILTERING_BILINEAR) c = texture(checker_bilinear, v_uv).rgb;
    else if (params.filtering == FILTERING_TRILINEAR) c = texture(checker_trilinear, v_uv).rgb;
    else {
        float lod = textureQueryLod(checker_trilinear, v_uv).y;
        const vec3 tint[6] = vec3[](vec3(1, 0.2, 0.2), vec3(1, 0.6, 0.1), vec3(0.9, 0.9, 0.1),
                                    vec3(0.2, 0.9, 0.2), vec3(0.2, 0.6, 1.0), vec3(0.7, 0.3, 1.0));
        c = tint[clamp(int(lod), 0, 5)] * (0.6 + 0.4 * texture(checker_trilinear, v_uv).r);
    }
    color = vec4(c, 1.0);
}
