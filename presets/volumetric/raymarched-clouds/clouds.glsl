// Clouds as a density modulation of the Mie term (002_644d46bdce7e5305.txt L2330, L2382-2403):
// the atmosphere library adds atmo_cloud_density() to the Mie density at every sample, the view
// ray's and the sun ray's alike, so clouds scatter (Mie phase: a bright silver lining towards the
// sun) and shadow the air below them.
//
//   cloudMap(p) = pow(max(0, smoothstep(0.44, 0.64, cloudFBM(p * 2e-4))), 2) * uCloudFactor
//   d(h) = cloudMap(p + wind) * sin(pi (h - bottom) / (top - bottom))   for bottom < h < top, else 0
//
// The slab: bottom 5000 m; top 15000 m in the table (L2315), 10000 m in the code (L2369): the
// param cloud_top defaults to the code's. The seed offsets p by (23175.7, 0, -t 3e3) with `t`
// the scatter function's uninitialised local (L2401, L2426): here t = params.cloud_time.
// Params read: cloud_factor, cloud_bottom, cloud_top, cloud_time.
#ifndef RAYMARCHED_CLOUDS_GLSL
#define RAYMARCHED_CLOUDS_GLSL

// The seed's value noise (L2381-2390): a sin hash of the lattice corners, smoothstep-blended.
float cloud_noise(const in vec3 p) {
    vec3 f = fract(p);
    f = (f * f) * (3.0 - (2.0 * f));
    float n = dot(floor(p), vec3(1.0, 57.0, 113.0));
    vec4 a = fract(sin(vec4(n + 0.0, n + 1.0, n + 57.0, n + 58.0)) * 43758.5453123);
    vec4 b = fract(sin(vec4(n + 113.0, n + 114.0, n + 170.0, n + 171.0)) * 43758.5453123);
    return mix(mix(mix(a.x, a.y, f.x), mix(a.z, a.w, f.x), f.y), mix(mix(b.x, b.y, f.x), mix(b.z, b.w, f.x), f.y), f.z);
}

// Six octaves, each rotated and scaled by ~2 (L2383-2393), normalised by the sum of weights.
float cloud_fbm(vec3 p) {
    float f = 0.0, m = 0.5, mm = 0.0, s = 0.0;
    for (int i = 0; i < 6; i++) {
        f += cloud_noise(p) * m;
        s += m;
        p *= mat3(0.00, 0.80, 0.60, -0.80, 0.36, -0.48, -0.60, -0.48, 0.64) * (2.0 + mm);
        m *= 0.5;
        mm += 0.0059;
    }
    return f / s;
}

float cloud_map(vec3 p) {
    return pow(max(0.0, smoothstep(0.4 + 0.04, 0.6 + 0.04, cloud_fbm(p * 2e-4))), 2.0) * params.cloud_factor;
}

// p: relative to the planet's centre; h: height above the ground (the library passes both).
float atmo_cloud_density(vec3 p, float h) {
    float bottom = params.cloud_bottom, top = params.cloud_top;
    if (!(bottom < h && h < top)) return 0.0;
    return cloud_map(p + vec3(23175.7, 0.0, -(params.cloud_time * 3e3))) * sin((3.1415 * (h - bottom)) / (top - bottom));
}
#endif
