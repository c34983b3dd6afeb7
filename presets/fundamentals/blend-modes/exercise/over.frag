#version 450
// EXERCISE — the over operator in a shader (000_c9f7e5de708ecbb3.txt L2041-2146): what the
// blend unit does with (SRC_ALPHA, ONE_MINUS_SRC_ALPHA), written out, for straight and for
// premultiplied colour, on the inputs of the `alpha` cell: source SRC over destination DST
// (defines; the destination is opaque). This file shadows the preset's over.frag.
//     passlab run   fundamentals/blend-modes --exercise presets/fundamentals/blend-modes/exercise
//     passlab grade fundamentals/blend-modes --exercise presets/fundamentals/blend-modes/exercise
// The results are not shown by the display (its ten cells are the blend unit's); the case
// over-in-a-shader reads them, or `passlab render ... --pass over --pass over_premul`.
// Both targets are rgba32f: no 8-bit rounding, the test compares with the formula exactly.
layout(location = 0) out vec4 over_out;           // straight over
layout(location = 1) out vec4 over_premul_out;    // premultiplied over (premultiplied result)

// TODO 1: straight over, s over d (colours not multiplied by their alpha):
//     C = Cs a + Cd (1 - a),   A = a + A_d (1 - a)
// The source covers a share a of the pixel and lets 1 - a of what is behind through: whose
// alpha is a, the source's or the destination's? The alpha channel composes by the same rule.
vec4 over_straight(vec4 s, vec4 d) {
    return s;
}

// TODO 2: a colour in premultiplied form: (C a, a), the colour weighted by its coverage.
vec4 premultiply(vec4 c) { return c; }

// TODO 3: premultiplied over, both s and d already premultiplied (TODO 2), the result too:
//     C' = Cs' + Cd' (1 - a)    and the same for A (the blend state (ONE, ONE_MINUS_SRC_ALPHA)).
// Cs' already carries the source's alpha: what must not happen to it here?
vec4 over_premultiplied(vec4 s, vec4 d) { return s; }

void main() {
    over_out = over_straight(SRC, DST);
    over_premul_out = over_premultiplied(premultiply(SRC), premultiply(DST));
}
