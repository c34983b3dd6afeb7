#version 450
// EXERCISE — noisy brick (004_9a40ad89bdfc582a.txt L445-487): the procedural brick of L209-260
// made less "clean" (L262-266) by noise in two places. This file shadows the preset's
// brick_noisy.frag; the plain brick's steps (brick_rel_pos, brick_is_mortar, brick_brightness)
// come from passes/procedural/brick.glsl, which you wrote in procedural/brick's exercise.
//     passlab run   procedural/brick-noisy --exercise presets/procedural/brick-noisy/exercise
//     passlab grade procedural/brick-noisy --exercise presets/procedural/brick-noisy/exercise
// `--set show=rel_pos` shows your shifted rel_pos as red and green.
// noise2 is not a Vulkan GLSL built-in (L433-443): gradient_noise2(vec3) (two signed noises,
// passes/procedural/noise_ext.glsl) stands in for it, gradient_noise(vec3) for a single one.
// With border_amp = 0 and color_var = 0 your wall must be the plain brick, bit for bit.
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

    // TODO 1: curvy brick edges (L453, L464-481): shift the position within the brick by
    // border_amp times a 2D noise of the model-space position at border_freq cycles per unit,
    //     rel_pos += border_amp * noise2(border_freq * P_model).
    // Where in the brick steps does the shift belong (L453 says "after fract()"), and in which
    // units is border_amp then measured?
    rel_pos += params.border_amp * gradient_noise2(params.border_freq * a_position_model);

    // TODO 2: the mortar test on the shifted position (L482-483): mortar where it lies past
    // BrickPercent along either axis (the plain test), and also where the shift has pushed it
    // below the brick's start.
    bool mortar = brick_is_mortar(rel_pos, params.brick_percent);   // MISTAKE: a shift below 0 is not mortar

    // TODO 3: the low-frequency colour variation of the bricks (L449): the brick colour scaled
    // by 1 + color_var * n, n a signed noise of the model-space position at color_freq.
    float variation = 1.0 + params.color_var * gradient_noise(params.color_freq * a_position_model);
    vec3 base = mortar ? params.mortar_color : params.brick_color * variation;
    color = params.show == SHOW_REL_POS ? vec4(rel_pos, 0.0, 1.0) : vec4(base * brightness, 1.0);
    mortar_out = mortar ? 1.0 : 0.0;
}
