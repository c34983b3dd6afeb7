#version 450
// EXERCISE — fill in the three TODO blocks; as shipped every pixel is unoccluded (A = 1).
//     passlab run   ao/ssao --exercise presets/ao/ssao/exercise --set show=raw
//     passlab grade ao/ssao --exercise presets/ao/ssao/exercise
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
    float visible = 0.0, total = 0.0;
    for (int i = 0; i < params.samples; ++i) {
        vec3 h = hash_pcg3(vec3(float(i), 71.0, 13.0));
        // Direction: uniform over the hemisphere (cos theta uniform).
        float cos_t = h.x, sin_t = sqrt(1.0 - cos_t * cos_t), phi = 6.2831853 * h.y;
        vec3 w = vec3(sin_t * cos(phi), sin_t * sin(phi), cos_t);
        float len = params.radius * mix(0.1, 1.0, h.z);
        // TODO 1: the sample point v_i and where it lands on screen. w is a unit direction in
        // the hemisphere's own frame (z along n), spun by `spin` about that z axis; `basis` takes
        // that frame to view space. Put the point at distance len from p along it, then project
        // it with frame.proj (view space -> clip space) to this pass's uv: NDC x, y in [-1, 1]
        // after the divide by w, uv = NDC * 0.5 + 0.5 (Vulkan: both y down).
        vec3 s = p;
        vec2 suv = uv;
        // TODO 3a: each sample's weight is the n . w_i of 004_9a40ad89bdfc582a.txt L722 (in the
        // hemisphere's frame n is the z axis). Every sample adds its weight to total.
        float weight = 1.0;
        total += weight;
        if (any(lessThan(suv, vec2(0.0))) || any(greaterThan(suv, vec2(1.0)))) {
            visible += weight;  // off screen: no information, count as open
            continue;
        }
        vec4 scene = texelFetch(vpos, ivec2(suv * frame.resolution.xy), 0);
        bool has_surface = texelFetch(normal, ivec2(suv * frame.resolution.xy), 0).w != 0.0;
        // TODO 2: "use z-buffer to check visibility of sample points v_i around receiver (wrt.
        // viewpoint!)" (004 L721). scene.xyz is the view-space position of the surface the
        // depth buffer holds at the sample's pixel. View space looks down -z: larger z is closer
        // to the eye. The sample is hidden when that surface is in front of it by more than
        // params.bias (against self-occlusion), and only counts as contact occlusion when that
        // surface is within 2 * params.radius of the receiver p in depth (a distant wall in
        // front is not).
        bool hidden = false;
        if (!hidden) visible += weight;
    }
    // TODO 3b: A = sum of the visible samples' weights / sum of all weights (004 L722, divided
    // by the total weight rather than the sample count so that an open hemisphere gives 1).
    ao_raw = 1.0;
}
