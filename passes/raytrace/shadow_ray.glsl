// The shadow ray of the supraleiter engine (002_644d46bdce7e5305.txt L2162-2168), for the
// ray-traced shadow presets (rt-hard-shadows, rt-soft-shadows):
//     sunLit = staticBVHRayShootForVisibilityCheck(vWorldSpacePosition + ((gNormal - uSunDirection)
//              * 0.01), uSunDirection, 0.01, 16777216.0, ...) ? 0.0 : 1.0;
// (the listing calls `staticBVHRayShootForVisibilityCheck` but defines `bvhRayShootForVisibilityCheck`,
// L2092: the same function; here it is rt_trace_ray with the any-hit flags, stages.glsl).
//
// Why the odd origin: from P + (N - L) 0.01 the ray along L with tmin = 0.01 starts counting at
// P + (N - L) 0.01 + 0.01 L = P + 0.01 N: the -L part exactly cancels tmin, so the segment begins
// 0.01 above the surface along its normal and never meets the triangle P lies on (a ray from P
// itself with tmin 0 hits it at t ~ +-1e-7, at random: shadow acne). 16777216 = 2^24, "infinity".

// The ray's flags: any hit ends the search, no closest-hit stage; the miss stage says "lit"
// (000_c9f7e5de708ecbb3.txt L5765-5770).
const uint SHADOW_RAY_FLAGS = RT_FLAG_ACCEPT_FIRST_HIT_AND_END_SEARCH | RT_FLAG_SKIP_CLOSEST_HIT_SHADER;

// The shadow ray from the surface point p with unit normal n towards the light along the unit l
// (the sun's direction, or a direction sampled on its disc). Needs raytrace/stages.glsl.
RtRay shadow_ray(vec3 p, vec3 n, vec3 l) {
    return RtRay(p + (n - l) * 0.01, 0.01, l, 16777216.0);
}
