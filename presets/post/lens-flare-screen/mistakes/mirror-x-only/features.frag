#version 450
// Stage 2 of 002_644d46bdce7e5305.txt L922-944 (getLensflare), at quarter resolution:
//   t = 1 - uv                              the image mirrored through the centre
//   ghostVec = (0.5 - t) * dispersal         steps from t towards (and past) the centre
//   ghosts:  sum_i blurred(t + i ghostVec) * w(t + i ghostVec) * lensColour(|0.5 - t'| / |0.5|)
//   halo:    blurred(t + normalize(ghostVec) * haloWidth) * w(...)
//   w(o)   = max(0, 1 - |0.5 - o| / |(0.5, 0.5)|)^10     bright near the centre only
// with each channel sampled shifted along the ghost direction by -d, 0, +d texels (chromatic
// distortion). Pitfalls of the listing, fixed as the equation says: its w has an extra ')' that
// makes it 1 - (|0.5| - o)/|0.5|; and it hard-codes a 16:9 aspect — we use the view's.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 flare;
uniform sampler2D blurred;
uniform sampler2D lens_ramp;

const float kHalfDiagonal = 0.70710678;  // |(0.5, 0.5)|

float weight(vec2 o) { return pow(max(0.0, 1.0 - length(vec2(0.5) - o) / kHalfDiagonal), 10.0); }

vec3 distorted(vec2 coord, vec2 dir, vec3 d) {
    return vec3(textureLod(blurred, coord + dir * d.r, 0.0).r, textureLod(blurred, coord + dir * d.g, 0.0).g,
                textureLod(blurred, coord + dir * d.b, 0.0).b);
}

void main() {
    float aspect = frame.aspect, inv_aspect = 1.0 / aspect;
    vec2 t = vec2(1.0 - uv.x, uv.y);   // mirrored left to right
    vec2 ghost_vec = (vec2(0.5) - t) * params.dispersal;
    vec2 g = ghost_vec * vec2(1.0, inv_aspect);
    // Unit direction in aspect-corrected space (0 at the exact centre: no direction, no shift).
    vec2 dir = dot(g, g) > 0.0 ? normalize(g) * vec2(1.0, aspect) : vec2(0.0);
    vec2 halo_vec = dir * params.halo_width;
    vec2 texel = 1.0 / vec2(textureSize(blurred, 0));
    vec3 d = vec3(-texel.x * params.distortion, 0.0, texel.x * params.distortion);
    vec3 c = vec3(0.0);
    for (int i = 0; i < params.ghosts; ++i) {
        vec2 o = t + ghost_vec * float(i);
        c += distorted(o, dir, d) * weight(o);
    }
    // 002 samples the colour ramp at the mirrored, aspect-corrected distance from the centre.
    vec2 aspect_t = vec2(1.0) - ((uv - 0.5) * vec2(1.0, inv_aspect) + 0.5);
    vec3 tint = params.lens_color ? textureLod(lens_ramp, vec2(length(vec2(0.5) - aspect_t) / kHalfDiagonal, 0.5), 0.0).rgb : vec3(1.0);
    vec2 halo_at = t + halo_vec;
    flare = vec4(c * tint + distorted(halo_at, dir, d) * weight(halo_at), 1.0);
}
