#version 450
// EXERCISE — the lens flare's features, stage 2 of 002_644d46bdce7e5305.txt (L922-944,
// getLensflare), at quarter resolution. `blurred` holds the thresholded, blurred bright parts;
// your shader writes, for each output texel uv, the ghosts and the halo that land on it.
// Fill in the three TODO blocks, then check your work against the reference:
//     passlab run   post/lens-flare-screen --exercise presets/post/lens-flare-screen/exercise --set show=flare
//     passlab grade post/lens-flare-screen --exercise presets/post/lens-flare-screen/exercise
// Given: weight(o) = max(0, 1 - |0.5 - o| / |(0.5, 0.5)|)^10 (bright near the centre only; the
// listing's extra ')' fixed), distorted(coord, dir, d) (each channel sampled shifted along dir by
// -d, 0, +d: the chromatic distortion), and the lens-colour tint. uv (0, 0) is the top-left
// corner, (0.5, 0.5) the centre c of the screen.
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
    // TODO 1: a lens images a bright point p as ghosts on the line through p and the centre c,
    // starting from p mirrored through the centre (L925): the point 2c - p. Let t be that
    // mirrored point of this texel's uv, and ghost_vec the step from t towards (and past) the
    // centre, (c - t) scaled by params.dispersal (L926).
    vec2 t = uv;
    vec2 ghost_vec = vec2(0.0);
    vec2 g = ghost_vec * vec2(1.0, inv_aspect);
    // Unit direction in aspect-corrected space (0 at the exact centre: no direction, no shift).
    vec2 dir = dot(g, g) > 0.0 ? normalize(g) * vec2(1.0, aspect) : vec2(0.0);
    vec2 halo_vec = dir * params.halo_width;
    vec2 texel = 1.0 / vec2(textureSize(blurred, 0));
    vec3 d = vec3(-texel.x * params.distortion, 0.0, texel.x * params.distortion);
    vec3 c = vec3(0.0);
    // TODO 2: the ghosts (L934-938): for i = 0 .. params.ghosts - 1, sample the blurred image
    // (with the chromatic distortion along dir) at o_i = t + i ghost_vec and add it to c,
    // weighted by weight(o_i).

    // 002 samples the colour ramp at the mirrored, aspect-corrected distance from the centre.
    vec2 aspect_t = vec2(1.0) - ((uv - 0.5) * vec2(1.0, inv_aspect) + 0.5);
    vec3 tint = params.lens_color ? textureLod(lens_ramp, vec2(length(vec2(0.5) - aspect_t) / kHalfDiagonal, 0.5), 0.0).rgb : vec3(1.0);
    // TODO 3: the halo (L939-943): one more sample, at halo_vec from t (a ring of radius
    // halo_width about the centre), weighted like a ghost; the ghosts are tinted by the lens
    // colour, the halo is not. Write the sum.
    flare = vec4(c * tint, 1.0);
}
