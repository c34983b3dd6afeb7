#version 450
// EXERCISE — one fragment shader, several outputs (000_c9f7e5de708ecbb3.txt L2026-2039). The
// offscreen pass attaches three colour targets, in this order (preset.toml `targets`):
//     location 0 -> rt_color   (the teapot's lit colour: the left box shows it)
//     location 1 -> rt_normal  (its normal: the right box shows it)
//     location 2 -> rt_same    (the colour again, for the test two-targets-one-value)
// Fill in the three TODO blocks, then check your work against the reference:
//     passlab run   post/render-to-texture-mrt --exercise presets/post/render-to-texture-mrt/exercise
//     passlab grade post/render-to-texture-mrt --exercise presets/post/render-to-texture-mrt/exercise
layout(location = 0) in vec3 v_normal;
layout(location = 0) out vec4 color0;
layout(location = 1) out vec4 color1;
layout(location = 2) out vec4 color2;
void main() {
    vec3 n = normalize(v_normal);
    // The lit colour (given): an ambient 0.2 plus a diffuse 0.8 max(n.l, 0), times the tint.
    vec3 c = params.tint * (0.2 + 0.8 * max(dot(n, normalize(vec3(0.5, 0.8, 0.6))), 0.0));
    // TODO 1: write the lit colour c (alpha 1) to the output that feeds rt_color.

    // TODO 2: write the normal to the output that feeds rt_normal, so that the texture a later
    // pass samples (and the box shows) holds it as a colour: each component of the unit normal
    // lies in [-1, 1] and must be mapped affinely onto [0, 1] (-1 -> 0, 0 -> 1/2, 1 -> 1).

    // TODO 3: location 2 receives the very same value as rt_color (bit for bit).
    color0 = color1 = color2 = vec4(0.0, 0.0, 0.0, 1.0);
}
