#version 450
// Noisy brick, 004_9a40ad89bdfc582a.txt L445-487: the brick of L209-260 (shared steps in
// passes/procedural/brick.glsl) made less "clean" (L262-266) by noise in two places:
//   4) colour variation (low frequency, L449):
//        BrickColor * (1 + color_var * n(color_freq * P_model))
//   5) curvy brick edges (L453, L464-487), after fract():
//        rel_pos += border_amp * noise2(border_freq * P_model)
//        outside_brick = any(greaterThan(rel_pos, BrickPercent)) || any(lessThan(rel_pos, 0))
// The second test (L482-483): a shift can push rel_pos below 0, which is mortar too. noise2 is not
// a Vulkan GLSL built-in (L433-443); gradient_noise2 (passes/procedural/noise_ext.glsl) stands
// in for it. With border_amp = 0 and color_var = 0 every value below is the plain brick's, bit
// for bit: rel_pos + 0 * n = rel_pos, fract() >= 0, and BrickColor * (1 + 0 * n) = BrickColor.
#include "procedural/brick.glsl"
#include "procedural/noise_ext.glsl"
layout(location = 0) in vec3 a_position_model;
layout(location = 1) in vec3 a_position_world;
layout(location = 2) in vec3 a_normal_world;
layout(location = 0) out vec4 color;
layout(location = 1) out float mortar_out;   // 1 = mortar of the noisy brick, 0 = brick
layout(location = 2) out float plain_out;    // 1 = mortar of the plain brick (the reference)

void main() {
    float brightness = brick_brightness(params.light_pos, a_position_world, a_normal_world);
    vec2 rel_pos = brick_rel_pos(a_position_model.xy, params.brick_size);  // brick_size min 0.01
    plain_out = brick_is_mortar(rel_pos, params.brick_percent) ? 1.0 : 0.0;

    rel_pos += params.border_amp * gradient_noise2(params.border_freq * a_position_model);
    bool mortar = brick_is_mortar(rel_pos, params.brick_percent) || any(lessThan(rel_pos, vec2(0.0)));

    float variation = 1.0 + params.color_var * gradient_noise(params.color_freq * a_position_model);
    vec3 base = mortar ? params.mortar_color : params.brick_color * variation;
    color = params.show == SHOW_REL_POS ? vec4(rel_pos, 0.0, 1.0) : vec4(base * brightness, 1.0);
    mortar_out = mortar ? 1.0 : 0.0;
}
