#version 450
// A surface point facing n receives the flux travelling towards it, i.e. along -n: the share
// lpv_face_flux gives the face -n of the accumulated lobe at x (trilinear, half a cell in front
// of the surface), over the face's area: E = F(-n) / cell^2, and reflects L = (rho / pi) E.
// Only the indirect light is shown (no direct term: the LPV carries the first bounce).
#include "gi/lpv_grid.glsl"
#include "gi/cornell.glsl"

uniform sampler3D sh_r;
uniform sampler3D sh_g;
uniform sampler3D sh_b;

layout(location = 0) in vec3 object_pos;
layout(location = 1) flat in int instance;
layout(location = 2) in vec3 world_pos;
layout(location = 3) in vec3 world_normal;
layout(location = 0) out vec4 color;

void main() {
    vec3 n = normalize(world_normal);
    vec3 uvw = (world_pos + n * (0.5 * LPV_CELL) + 1.0) * 0.5;
    vec4 r = textureLod(sh_r, uvw, 0.0), g = textureLod(sh_g, uvw, 0.0), b = textureLod(sh_b, uvw, 0.0);
    vec3 c0 = vec3(r.x, g.x, b.x), c1 = vec3(0.0);
    // flux along -n: weight max(0, c0 + 3 c1 . (-n)) / 6 of c0 (unnormalised form of lpv_face_flux)
    vec3 proj = -(vec3(r.y, g.y, b.y) * n.x + vec3(r.z, g.z, b.z) * n.y + vec3(r.w, g.w, b.w) * n.z);
    vec3 flux = max(vec3(0.0), c0 + 3.0 * proj) / 6.0;
    vec3 l = cornell_albedo(MESH, instance) / 3.14159265 * flux / (LPV_CELL * LPV_CELL);
    color = vec4(l * params.exposure, 1.0);
}
