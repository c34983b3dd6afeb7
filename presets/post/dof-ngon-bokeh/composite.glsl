// The half-resolution composite (not 002's; see dof.frag RESOLUTION), shared by display.frag
// and composite_check.frag so that the tests check the image the display shows:
//   resolution = half: the gather is view/2 (upsampled bilinearly); where the blur is under
//   kSharpBelow px the 2x2 box of the half-res source would soften an in-focus surface, so the
//   full-res input is shown there, the gather from kSharpBelow + 1 px on (linear between):
//     out = mix(sharp, gathered, clamp(blur - kSharpBelow, 0, 1))
//   resolution = full: the gather itself.
// The three fetches are made unconditionally and the result selected (lavapipe fetches inside
// an untaken branch anyway; straight code lets display.frag share them): the same values.
const float kSharpBelow = 1.0;
vec4 dof_composite(sampler2D color, sampler2D result, sampler2D blur, vec2 uv) {
    vec4 sharp = textureLod(color, uv, 0.0), blurred = texture(result, uv);
    vec4 mixed = mix(sharp, blurred, clamp(texture(blur, uv).x - kSharpBelow, 0.0, 1.0));
    return params.resolution == RESOLUTION_HALF ? mixed : blurred;
}
