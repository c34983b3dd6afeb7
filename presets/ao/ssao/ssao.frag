#version 450
// Screen-space ambient occlusion (000_c9f7e5de708ecbb3.txt L4901-4911; 003_cfc3b5b225ddab3d.txt
// L327-356; 004_9a40ad89bdfc582a.txt L717-723): around the receiver p with normal n, sample
// points v_i in the hemisphere of radius d; a point is hidden when the depth buffer, at the
// pixel it projects to, holds a surface in front of it (seen from the viewpoint, 004 L721).
//   A ~ sum over visible v_i of n.w_i  /  sum over all v_i of n.w_i        (004 L722, normalised
//                                                                          so open sky gives 1)
// Samples: a fixed hemisphere kernel (lengths uniform in [0.1 d, d]), turned about n by one of 16 angles chosen
// by the pixel's position in a 4x4 tile (the blur pass then averages the 16 rotations away).
// A range check ignores occluders much farther than d (a distant wall in front is not contact
// occlusion).
#include "common/hash.glsl"
#include "common/sampling.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out float ao_raw;
uniform sampler2D normal;
uniform sampler2D vpos;
uniform sampler2D vz;  // view z alone, 0 on the background

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec4 nw = texelFetch(normal, px, 0);
    if (nw.w == 0.0) {  // background: nothing to occlude
        ao_raw = 1.0;
        return;
    }
    vec3 n = normalize(nw.xyz), p = texelFetch(vpos, px, 0).xyz;
    mat3 basis = basis_from_normal(n);
    ivec2 tile = px % 4;
    float turn = 6.2831853 * float(tile.x + 4 * tile.y) / 16.0;
    mat3 spin = mat3(cos(turn), sin(turn), 0, -sin(turn), cos(turn), 0, 0, 0, 1);
    mat3 to_view = basis * spin;  // spin about n, then the hemisphere's frame to view space
    float visible = 0.0, total = 0.0;
    for (int i = 0; i < params.samples; ++i) {
        vec3 h = hash_pcg3(vec3(float(i), 71.0, 13.0));
        // Direction: uniform over the hemisphere (cos theta uniform).
        float cos_t = h.x, sin_t = sqrt(1.0 - cos_t * cos_t), phi = 6.2831853 * h.y;
        vec3 w = vec3(sin_t * cos(phi), sin_t * sin(phi), cos_t);
        float len = params.radius * mix(0.1, 1.0, h.z);
        vec3 s = p + to_view * w * len;
        vec4 clip = frame.proj * vec4(s, 1.0);
        vec2 suv = clip.xy / clip.w * 0.5 + 0.5;
        float weight = cos_t;  // n . w_i
        total += weight;
        if (any(lessThan(suv, vec2(0.0))) || any(greaterThan(suv, vec2(1.0)))) {
            visible += weight;  // off screen: no information, count as open
            continue;
        }
        // The test needs only the depth of the surface there: `vz` holds vpos.z alone (4 bytes
        // a texel instead of 16, so the scattered fetches stay in cache), and 0 where the clear
        // left the background (geometry in front of the eye has z < 0): one fetch tells both.
        float scene_z = texelFetch(vz, ivec2(suv * frame.resolution.xy), 0).r;
        bool has_surface = scene_z != 0.0;
        // View space looks down -z: larger z is closer to the eye.
        bool hidden = has_surface && scene_z >= s.z + params.bias && abs(p.z - scene_z) < 2.0 * params.radius;
        if (!hidden) visible += weight;
    }
    ao_raw = visible / max(total, 1e-6);
}
