#version 450
// Row 0 of the solution: what each patch sends out before any interreflection, its emission
// plus the spot light reflected once, L0_i = Le_i + (rho_i / pi) E_direct,i, the patch average of
// the direct irradiance (visibility by a shadow ray) over RAD_DIRECT_N^2 jittered points (points
// inside a block, on a floor patch the block covers, are skipped).
layout(local_size_x = 64) in;

#include "gi/radiosity_trace.glsl"
#include "gi/radiosity_albedo.glsl"
#include "common/hash.glsl"

layout(std430) writeonly buffer Radiance { vec4 value[]; } radiance;

const int RAD_DIRECT_N = 4;

void main() {
    int p = int(gl_GlobalInvocationID.x);
    if (p >= RAD_PATCHES) return;
    RadSurface s = radiosity_surface(radiosity_surface_of_patch(p));
    int walls = params.closed ? RAD_WALLS : CORNELL_WALLS;
    vec3 value;
    if (p < RAD_LIVE_PATCHES && !(s.mesh == 0 && s.instance >= walls)) {
        mat4 m = radiosity_world_from_object(s);
        vec3 n = radiosity_world_normal(s);
        int local = p - s.first, counted = 0;
        vec3 irradiance = vec3(0.0);
        for (int j = 0; j < RAD_DIRECT_N * RAD_DIRECT_N; ++j) {
            vec2 cell = vec2(j % RAD_DIRECT_N, j / RAD_DIRECT_N) + hash_pcg3(vec3(p, j, 3)).xy;
            vec2 ab = clamp((vec2(local % s.n, local / s.n) + cell / float(RAD_DIRECT_N)) / float(s.n), 1e-3, 1.0 - 1e-3);
            vec3 x = (m * vec4(radiosity_object_point(s, ab), 1.0)).xyz;
            if (radiosity_trace_patch(x, n, walls) == -2) continue;  // under a block
            ++counted;
            if (!radiosity_occluded(x, CORNELL_LIGHT_POS, walls)) irradiance += cornell_light_irradiance(x, n);
        }
        // A sliver patch whose 16 points all fall under a block gets no direct light; whether a
        // patch is hidden altogether is decided by its 256 form-factor rays (gather.comp).
        value = params.emission + params.light * radiosity_albedo(s) / 3.14159265 * irradiance / float(max(counted, 1));
    } else {
        value = vec3(-1.0);  // no surface (see gather.comp)
    }
    radiance.value[p] = vec4(value, 1.0);
}
