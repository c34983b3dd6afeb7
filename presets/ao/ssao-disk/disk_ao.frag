#version 450
// Screen-space ambient occlusion, "method 2" of 004_9a40ad89bdfc582a.txt L727-735:
//   - every pixel re-projected to its camera-space point: the receiver p, normal n;
//   - the neighbourhood radius R converted to a radius on screen; every pixel within
//     (here every `stride`-th, see below) re-projected: sample points q_i;
//   - the surface around each q_i approximated by a disk F_i of radius r_i, oriented towards
//     the receiver, projected onto the receiver's hemisphere (F'_i), accumulated:
//         A ~ sum over |q_i - p| < R of F'_i n.(q_i - p) = sum F_i / d_i^2 n.(q_i - p)   (L735)
// As printed, n.(q_i - p) is not normalised: F_i/d_i^2 is a solid angle, n.(q_i - p) a length,
// and A would grow with the scene's scale. The projected solid angle needs the cosine,
// n.(q_i - p) / d_i: used here (a stated fix). Normalised by the hemisphere's projected solid
// angle pi, the occlusion is O = (1/pi) sum w_i cos_i, and the visibility V = 1 - min(O, 1)
// (overlapping disks count twice: the sum can pass 1 — part of why AO "appears exaggerated",
// L755-761). Samples below the receiver's tangent plane (n.(q - p) <= 0) cannot occlude.
//   w_i = F_i / d_i^2                           disk_model = approx (as printed, d >> r)
//   w_i = 2 pi (1 - d_i / sqrt(d_i^2 + r_i^2))  disk_model = cap: the exact solid angle of a
//                                               facing disk (L743: "compute area of
//                                               spherical cap ... don't just scale F_i")
// F_i: the area of surface one sample stands for: (stride pixels)^2 at the sample's depth,
// divided by |n_q . view| (a tilted surface covers more area per pixel, clamped at 1/kMinCos),
// times disk_scale^2 (L739: "change ... radius of disks r_i").
// orientation = receiver: the disk faces the receiver (as printed, L731); = normal: it lies in
// the sample's tangent plane (L744: "orient disks perpendicular to normal in sample points"),
// which multiplies w_i by |n_q . (p - q)| / d_i, the disk's foreshortening seen from p — a wall
// seen edge-on from the receiver then stops counting in full.
#include "common/hash.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out float ao;
uniform sampler2D normal;
uniform sampler2D vpos;
const float kPi = 3.14159265358979;
const float kMinCos = 0.2;

void main() {
    // The receiver: this pixel of the g-buffer, or with ao_resolution = half every second one in
    // x and y (the ao image is half the view: a quarter of the receivers, each still gathering
    // its samples q_i from the full-resolution g-buffer; frame.resolution stays the view's).
    ivec2 px = ivec2(gl_FragCoord.xy) * (params.ao_resolution == AO_RESOLUTION_HALF ? 2 : 1);
    ivec2 size = ivec2(frame.resolution.xy);
    vec4 nw = texelFetch(normal, px, 0);
    if (nw.w == 0.0) {
        ao = 1.0;
        return;
    }
    vec3 n = normalize(nw.xyz), p = texelFetch(vpos, px, 0).xyz;
    // World size of one pixel at view depth z: z * 2 tan(fov/2) / height = 2 z / (|P11| height).
    float px_per_unit = abs(frame.proj[1][1]) * frame.resolution.y / (2.0 * -p.z);
    int reach = int(params.radius * px_per_unit);
    // The sample spacing: every `step`-th pixel, widened where R's screen disk is larger than
    // `taps` samples from centre to edge, so that R is honoured everywhere at a bounded cost
    // (a near receiver's disk can be hundreds of pixels wide). Each sample then stands for
    // stride^2 pixels of surface (F_i below), so the sum estimates the same integral.
    int stride = max(params.step, (reach + params.taps - 1) / params.taps);
    reach = reach / stride * stride;   // the ring of samples ends on the grid
    // A spaced-out grid repeats the same offsets at every pixel, and the occlusion shows its
    // pattern (rings and bands around objects). Where stride > 1 the grid is rotated by a
    // per-pixel random angle: the same number of samples, each still standing for stride^2
    // pixels on average, with the pattern turned into fine noise.
    float angle = stride > 1 ? 6.28318530718 * hash_pcg(vec3(px, 0.0)) : 0.0;
    mat2 rot = mat2(cos(angle), sin(angle), -sin(angle), cos(angle));
    // Per-receiver constants of the loop below: a sample's pixel side is its view depth times
    // this (2 z / (|P11| height), times stride), and the disk radius factor disk_scale^2.
    float side_per_depth = float(stride) * 2.0 / (abs(frame.proj[1][1]) * frame.resolution.y);
    float scale2 = params.disk_scale * params.disk_scale;
    float occlusion = 0.0;
    for (int y = -reach; y <= reach; y += stride) {
        // Only the grid points inside the disk x^2 + y^2 <= reach^2: this row's half-width,
        // the largest multiple of stride not past sqrt(reach^2 - y^2) (the float root, then
        // corrected by one step either way in integers), instead of the whole square.
        int r2 = reach * reach - y * y;
        int span = int(sqrt(float(r2))) / stride * stride;
        if ((span + stride) * (span + stride) <= r2) span += stride;
        if (span * span > r2) span -= stride;
        for (int x = -span; x <= span; x += stride) {
            if (x == 0 && y == 0) continue;
            ivec2 q_px = px + ivec2(round(rot * vec2(x, y)));
            if (any(lessThan(q_px, ivec2(0))) || any(greaterThanEqual(q_px, size))) continue;
            // vpos.w is 1 on geometry, 0 on the cleared background; the sample's normal is
            // fetched only once it lies within R and above the tangent plane.
            vec4 qw = texelFetch(vpos, q_px, 0);
            if (qw.w == 0.0) continue;
            vec3 q = qw.xyz, pq = q - p;
            float d2 = dot(pq, pq), inv_d = inversesqrt(d2), d = d2 * inv_d, h = dot(n, pq);
            if (d >= params.radius || h <= 0.0) continue;
            vec3 nq = normalize(texelFetch(normal, q_px, 0).xyz);
            float pixel = side_per_depth * -q.z;
            float facing = max(abs(dot(nq, q)) * inversesqrt(dot(q, q)), kMinCos);  // |n_q . view|
            float area = pixel * pixel / facing * scale2;  // F_i
            float w = params.disk_model == DISK_MODEL_CAP ? 2.0 * kPi * (1.0 - d * inversesqrt(d2 + area / kPi))
                                                          : area / d2;
            if (params.orientation == ORIENTATION_NORMAL) w *= abs(dot(nq, pq)) * inv_d;
            occlusion += w * h * inv_d;
        }
    }
    ao = 1.0 - min(occlusion / kPi, 1.0);
}
