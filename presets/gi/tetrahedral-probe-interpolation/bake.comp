#version 450
// The probes (offline in the seed, L2811: "offline tessellated ... and then prebaked"): each probe
// projects the radiance it sees onto 9 SH coefficients, c_i = integral L(w) y_i(w) dw, estimated
// with TP_RAYS stratified directions of uniform density (4 pi / TP_RAYS sr each). The radiance a
// ray brings is the spot's light reflected once by the surface it hits, (rho / pi) E_direct with
// a shadow ray (0 when it leaves through the open front): what the probes carry is the first
// indirect bounce.
layout(local_size_x = 16) in;

#include "gi/tetrahedral_probes.glsl"
#include "gi/tetrahedral_sh.glsl"
#include "gi/radiosity_trace.glsl"

layout(std430) writeonly buffer Probes { vec4 coeff[]; } probes;

const int TP_SIDE = 32, TP_RAYS = TP_SIDE * TP_SIDE;

void main() {
    int p = int(gl_GlobalInvocationID.x);
    if (p >= TP_PROBES) return;
    vec3 x = tetrahedral_probe_position(p);
    vec3 c[9];
    for (int i = 0; i < 9; ++i) c[i] = vec3(0.0);
    for (int k = 0; k < TP_RAYS; ++k) {
        // stratum (i, j) of (cos theta in [-1, 1], phi): uniform over the sphere
        float z = 1.0 - 2.0 * (float(k % TP_SIDE) + 0.5) / float(TP_SIDE);
        float phi = 6.28318530718 * (float(k / TP_SIDE) + 0.5) / float(TP_SIDE);
        float r = sqrt(max(0.0, 1.0 - z * z));
        vec3 d = vec3(r * cos(phi), r * sin(phi), z);
        RadHit h = radiosity_trace(x, d, CORNELL_WALLS);
        vec3 l = vec3(0.0);
        if (h.found && !h.back) {
            RadSurface s = radiosity_surface(h.surface);
            vec3 y = x + h.t * d, n = radiosity_world_normal(s);
            if (!radiosity_occluded(y + n * 1e-4, CORNELL_LIGHT_POS, CORNELL_WALLS))
                l = cornell_albedo(s.mesh, s.instance) / 3.14159265 * cornell_light_irradiance(y, n);
        }
        float sh[9];
        tetrahedral_sh9(d, sh);
        for (int i = 0; i < 9; ++i) c[i] += l * sh[i];
    }
    for (int i = 0; i < 9; ++i) probes.coeff[p * TP_SH + i] = vec4(c[i] * (12.5663706 / float(TP_RAYS)), 0.0);
}
