#version 450
// Reflective shadow map (002_644d46bdce7e5305.txt L2599-2615: "shadow maps with additional color
// and normal informations"; 000_c9f7e5de708ecbb3.txt L5332-5359: each texel a light), rendered
// from the spot's camera. A texel sees the solid angle dw = (2 tan(fov/2) / W)(2 tan(fov/2) / H)
// cos^3(alpha) (alpha from the camera axis); all of I(w) dw lands on the patch it sees, which
// reflects rho I(w) dw diffusely: that is the texel's flux, whatever the patch's orientation.
// Targets: flux (rgb), world normal, world position with w = distance to the light (the shadow
// map of the direct term).
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 2) flat in vec3 v_albedo;
layout(location = 0) out vec4 rsm_flux;
layout(location = 1) out vec4 rsm_normal;
layout(location = 2) out vec4 rsm_pos;
#include "gi/cornell.glsl"
void main() {
    vec3 d = v_world - CORNELL_LIGHT_POS;
    float dist = length(d);
    vec3 w = d / dist;
    float cos_a = dot(w, CORNELL_LIGHT_DIR);
    // frame.proj is the light camera's: proj[0][0] = 1 / (aspect tan(fov/2)), |proj[1][1]| = 1 / tan(fov/2).
    vec2 texel = 2.0 / (abs(vec2(frame.proj[0][0], frame.proj[1][1])) * frame.resolution.xy);
    float dw = texel.x * texel.y * cos_a * cos_a * cos_a;
    vec3 n = normalize(v_normal);
    if (dot(n, w) > 0.0) n = -n;  // the side the light sees
    rsm_flux = vec4(v_albedo * cornell_light_intensity(w) * dw, 1.0);
    rsm_normal = vec4(n, 0.0);
    rsm_pos = vec4(v_world, dist);
}
