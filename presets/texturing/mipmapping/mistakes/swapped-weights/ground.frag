#version 450
// EXERCISE — mipmapping (000_c9f7e5de708ecbb3.txt L1778-1885): do by hand what the trilinear
// sampler does. The reference shader asks the hardware (texture(checker_trilinear, uv)); here
// you pick the mip level and blend the two nearest levels yourself, and the grade compares your
// pictures with the hardware's.
//     passlab run   texturing/mipmapping --exercise presets/texturing/mipmapping/exercise
//     passlab grade texturing/mipmapping --exercise presets/texturing/mipmapping/exercise
// checker_bilinear has the whole chain with mip_filter = nearest: textureLod(checker_bilinear,
// uv, k) for a whole number k reads level k alone, bilinearly filtered.
layout(location = 0) in vec2 v_uv;
layout(location = 0) out vec4 color;
uniform sampler2D checker_nearest;
uniform sampler2D checker_bilinear;
uniform sampler2D checker_trilinear;

// The level of detail D at uv.
float mip_level(vec2 uv) {
    vec2 t = uv * vec2(textureSize(checker_bilinear, 0));
    return log2(max(length(dFdx(t)), length(dFdy(t))));
}

// Trilinear filtering: blend the two levels either side of D.
vec3 trilinear(vec2 uv) {
    float d = clamp(mip_level(uv), 0.0, float(textureQueryLevels(checker_bilinear) - 1));
    float d0 = floor(d), d1 = d0 + 1.0;
    return (d - d0) * textureLod(checker_bilinear, uv, d0).rgb
         + (d1 - d) * textureLod(checker_bilinear, uv, d1).rgb;
}

void main() {
    vec3 c;
    if (params.filtering == FILTERING_COMPARE) {
        // Split view, thirds of the screen: nearest | bilinear | trilinear. All three are sampled
        // in uniform control flow (the sampler's derivatives need the whole 2x2 quad), then one
        // is kept; a thin line marks each border.
        vec3 n = texture(checker_nearest, v_uv).rgb, b = texture(checker_bilinear, v_uv).rgb;
        vec3 t = trilinear(v_uv);
        float x = gl_FragCoord.x / frame.resolution.x;
        c = x < 1.0 / 3.0 ? n : x < 2.0 / 3.0 ? b : t;
        if (abs(x - 1.0 / 3.0) < 0.0015 || abs(x - 2.0 / 3.0) < 0.0015) c = vec3(1.0, 0.8, 0.2);
    } else if (params.filtering == FILTERING_NEAREST) c = texture(checker_nearest, v_uv).rgb;
    else if (params.filtering == FILTERING_BILINEAR) c = texture(checker_bilinear, v_uv).rgb;
    else if (params.filtering == FILTERING_TRILINEAR) c = trilinear(v_uv);
    else {
        // show_level: colour by the level TODO 1 picks.
        float lod = mip_level(v_uv);
        const vec3 tint[6] = vec3[](vec3(1, 0.2, 0.2), vec3(1, 0.6, 0.1), vec3(0.9, 0.9, 0.1),
                                    vec3(0.2, 0.9, 0.2), vec3(0.2, 0.6, 1.0), vec3(0.7, 0.3, 1.0));
        c = tint[clamp(int(lod), 0, 5)] * (0.6 + 0.4 * trilinear(v_uv).r);
    }
    color = vec4(c, 1.0);
}
