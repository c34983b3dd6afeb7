#version 450
// Looking into the volume (the box [-1, 1]^3) along the view ray:
//   slices: three axis-aligned planes through `slice` (texture coordinates), the nearest hit;
//   fog:    emission-absorption ray march ("volumetric fog", L1774, named only):
//               T_{k+1} = T_k exp(-sigma o(d_k) dt),   C += T_k (1 - exp(-sigma o(d_k) dt)) colour(d_k)
//           with d_k = the trilinear sample of the 3D texture at step k and o(d) the opacity
//           part of the transfer function (the shell faint, the lesions dense, so they show).
// filtering: the same voxels through two samplers, `volume` (trilinear) and its alias
// `volume_nearest` (nearest voxel), both clamped to the edge. Two passes share this shader, one
// per sampler (preset.toml: `render_nearest` binds `volume` to the alias), so each step takes
// one sample (on lavapipe a branch between the two samplers would run both).
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 hdr;
uniform sampler3D volume;

float density(vec3 t) { return texture(volume, t).r; }

// The transfer function: a colour and an opacity per density — air, tissue (up to 0.3),
// shell (0.3 .. 0.65), lesions (above).
vec3 transfer(float d) {
    return d < 0.3 ? mix(vec3(0.1, 0.15, 0.4), vec3(0.9, 0.45, 0.35), d / 0.3)
         : d < 0.65 ? vec3(0.85, 0.85, 0.9) : mix(vec3(1.0, 0.75, 0.15), vec3(1.0, 0.95, 0.5), (d - 0.65) / 0.35);
}

float opacity(float d) { return d < 0.3 ? 0.5 * d : d < 0.65 ? 0.25 * d : 4.0 * d; }

void main() {
    vec4 w = frame.inv_view_proj * vec4(uv * 2.0 - 1.0, 1.0, 1.0);
    vec3 o = frame.camera_pos.xyz, dir = normalize(w.xyz / w.w - o);
    vec3 bg = mix(vec3(0.02, 0.02, 0.03), vec3(0.08, 0.09, 0.12), uv.y);
    // ray / box slabs
    vec3 inv = 1.0 / dir, ta = (-1.0 - o) * inv, tb = (1.0 - o) * inv;
    float t0 = max(max(min(ta.x, tb.x), min(ta.y, tb.y)), max(min(ta.z, tb.z), 0.0));
    float t1 = min(min(max(ta.x, tb.x), max(ta.y, tb.y)), max(ta.z, tb.z));
    if (t1 <= t0) { hdr = vec4(bg, 1.0); return; }
    if (params.view == VIEW_SLICES) {
        vec3 plane = params.slice * 2.0 - 1.0;           // in box space
        vec3 tp = (plane - o) * inv;
        float best = 1e30;
        vec3 c = bg;
        for (int a = 0; a < 3; ++a) {
            float t = tp[a];
            vec3 p = o + t * dir;
            if (t > t0 - 1e-4 && t < t1 + 1e-4 && t < best) {
                best = t;
                float d = density(p * 0.5 + 0.5);
                c = transfer(d) * (0.25 + 0.75 * d) + (abs(p[(a + 1) % 3]) > 0.985 || abs(p[(a + 2) % 3]) > 0.985 ? vec3(0.4) : vec3(0.0));
            }
        }
        hdr = vec4(c, 1.0);
        return;
    }
    int steps = params.steps;
    float dt = (t1 - t0) / float(steps), transmittance = 1.0;
    vec3 c = vec3(0.0);
    // Empty space: outside the phantom's outer ellipsoid (phantom.glsl, radii r = (0.72, 0.9,
    // 0.8)) every voxel is 0, and a trilinear sample is 0 unless one of its 8 voxel centres
    // (within sqrt(3)/32 = 0.054) lies inside, i.e. unless the point lies in r * (1 + 0.054 /
    // 0.72) = 1.075 r. A sample of density 0 changes nothing (alpha = 1 - exp(0) = 0: c and the
    // transmittance stay exactly as they are), so only the steps whose sample points can lie
    // in the ellipsoid 1.1 r are taken, with one step of slack each side: the same sum, the same
    // sample positions, fewer samples of air.
    const vec3 kBound = 1.1 * vec3(0.72, 0.9, 0.8);
    vec3 qo = o / kBound, qd = dir / kBound;
    float qa = dot(qd, qd), qb = dot(qo, qd), qc = dot(qo, qo) - 1.0, disc = qb * qb - qa * qc;
    int k_first = steps, k_last = -1;   // no step: the line misses the ellipsoid
    if (disc >= 0.0) {
        float te0 = (-qb - sqrt(disc)) / qa, te1 = (-qb + sqrt(disc)) / qa;
        k_first = int(clamp(floor((te0 - t0) / dt - 0.5) - 1.0, 0.0, float(steps)));
        k_last = int(clamp(ceil((te1 - t0) / dt - 0.5) + 1.0, -1.0, float(steps - 1)));
    }
    for (int k = k_first; k <= k_last; ++k) {
        float d = density((o + (t0 + (float(k) + 0.5) * dt) * dir) * 0.5 + 0.5);
        float alpha = 1.0 - exp(-params.sigma * opacity(d) * dt);
        c += transmittance * alpha * transfer(d);
        transmittance *= 1.0 - alpha;
    }
    hdr = vec4(c + transmittance * bg, 1.0);
}
