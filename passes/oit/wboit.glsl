// Weighted blended OIT (McGuire & Bavoil 2013, jcgt.org/published/0002/02/09; the weight as
// 002_644d46bdce7e5305.txt L1760-1768 prints it; "Use depth as implicit weight (heuristic)",
// 000_c9f7e5de708ecbb3.txt L4147-4148). Shared by weighted-blended and the hybrid's tail.
//
// Every fragment adds (rgb * a, a) * w to an additive accumulator and multiplies the revealage
// (cleared to 1) by (1 - a); the resolve divides the weighted colour sum by the weighted alpha sum
// (a weighted average of the colours) and shows it with coverage 1 - revealage = 1 - prod(1 - a_i),
// which is exact: only the colour mix is approximate, weighted towards the near fragments.

// w = max(min(1, max(r, g, b) * a), a) * clamp(0.03 / (1e-5 + (z / 4096)^4), 1e-2, 3e3),
// z the view-space distance (L1762-1765): the weight falls with distance as z^-4.
float oit_wboit_weight(vec4 c, float viewZ) {
    float colorWeight = max(min(1.0, max(max(c.r, c.g), c.b) * c.a), c.a);
    return colorWeight * clamp(0.03 / (1e-5 + pow(viewZ / 4096.0, 4.0)), 1e-2, 3e3);
}
