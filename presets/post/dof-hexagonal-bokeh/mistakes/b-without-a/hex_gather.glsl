// EXERCISE — the hexagonal blur's directions (TODO 1, 2 here) and combination (TODO 3 in
// hex_pass1.frag, TODO 4 in hex_pass2.frag). Check your work against the reference:
//     passlab run   post/dof-hexagonal-bokeh --exercise presets/post/dof-hexagonal-bokeh/exercise
//     passlab grade post/dof-hexagonal-bokeh --exercise presets/post/dof-hexagonal-bokeh/exercise
// doGatherAndApply of 002_644d46bdce7e5305.txt L1318-1336, shared by both blur passes.
// One tap at pUV (bilinear), pStepDistance from the pixel (in units of the image height, as the
// CoC). It contributes if its blur circle reaches this far (|CoC| > step) and it is in the near
// field (near blur spills over everything) or both are far and its CoC is less than twice this
// pixel's (a far pixel does not smear over a sharper one). A near tap also carries its CoC into
// the result's alpha (the most negative wins), so later passes know the pixel is near-blurred.
// Its weight is the part of its circle beyond the step, clamped to [0, 1]:
//   fraction = clamp((|CoC| - step) * K, 0, 1)
// PITFALL (stated, not printed): 002 writes K = pInverseTextureSize.y, i.e. (|CoC| - step) in
// height units *divided* by the height again: never near 1, so the clamp never saturates and
// the weights fall off linearly with the distance (a cone, brighter at the centre) instead of a
// flat aperture with a one-pixel soft edge. FRACTION_PIXELS = 1 uses K = texture height (the
// difference in pixels); 0 keeps the printed factor. Both are normalised by the sum of the
// weights, so both keep the energy.
#ifndef PASSLAB_HEX_GATHER_GLSL
#define PASSLAB_HEX_GATHER_GLSL
float doGatherAndApply(sampler2D pTexSource, vec2 pUV, float pBaseCoC, float pStepDistance, vec2 pInverseTextureSize,
                       inout vec4 pColor) {
    vec4 lColor = textureLod(pTexSource, pUV, 0.0);
    bool lBlurNear = lColor.w < 0.0;
    float lAbsoluteCoC = abs(lColor.w), lSampleFraction = 0.0;
    if ((lAbsoluteCoC > pStepDistance) && (lBlurNear || ((pBaseCoC > 0.0) && (lAbsoluteCoC < (pBaseCoC * 2.0))))) {
        if (lBlurNear) {
            if (pColor.w < 0.0) {
                pColor.w = min(pColor.w, lColor.w);
            } else if ((-lColor.w) > pColor.w) {
                pColor.w = lColor.w;
            }
        }
        float k = params.fraction == FRACTION_PIXELS ? 1.0 / pInverseTextureSize.y : pInverseTextureSize.y;
        lSampleFraction = clamp((lAbsoluteCoC - pStepDistance) * k, 0.0, 1.0);
        pColor.xyz += lColor.xyz * lSampleFraction;
    }
    return lSampleFraction;
}

// The three directions of 002 (pass 1 L1356 and L1358, pass 2 L1386): up, and +-120 degrees from
// it. 002's texture coordinates have v up; ours (Vulkan) have v down, so "up" (0, 1) is (0, -1) here and the
// diagonals (+-0.866, -0.5) are (+-0.866, 0.5). The hexagon is symmetric about the horizontal
// axis, so the shape is the same; on screen it is the printed one.
// The pixel's own colour is read with texelFetch in the passes (002: textureLod at vTexCoord, the
// texel centre; an interpolated uv a rounding off the centre would mix in a neighbour).
// Per tap step the offset is one pixel long: x is scaled by the aspect (0.866 w_texel / h_texel).
// TODO 1: the three unit directions (002 L1356, L1358, L1386): up, and the two directions
// +-120 degrees from it (so the three blur lines are 60 degrees apart and the rhombi tile a
// hexagon with vertices up and down). Remember that v points down here.
const vec2 kUp = vec2(0.0, -1.0), kDownRight = vec2(0.866, 0.5), kDownLeft = vec2(-0.866, 0.5);
// TODO 2: the uv offset of one step along dir. The passes multiply it by a distance in units
// of the image height (lStepDistance), so y needs no change; x must be converted so that a
// step is as long across as it is down on a non-square texture (inv_size = 1 / texture size).
vec2 hex_step(vec2 dir, vec2 inv_size) { return vec2(dir.x * inv_size.x / inv_size.y, dir.y); }
#endif
