#version 450
// Procedural brick, 004_9a40ad89bdfc582a.txt L209-260 (the steps and equations are in
// passes/procedural/brick.glsl, shared with presets/procedural/brick-noisy):
//   rel_pos = fract(shift_odd_rows(position_model.xy / BrickStepSize))
//   colour  = any(greaterThan(rel_pos, BrickPercent)) ? MortarColor : BrickColor
//   fragColor = colour * clamp(dot(normal, light), 0, 1)
#include "procedural/brick.glsl"
layout(location = 0) in vec3 a_position_model;
layout(location = 1) in vec3 a_position_world;
layout(location = 2) in vec3 a_normal_world;
layout(location = 0) out vec4 color;
layout(location = 1) out float mortar_out;

void main() {
    float brightness = brick_brightness(params.light_pos, a_position_world, a_normal_world);
    vec2 rel_pos = brick_rel_pos(a_position_model.xy, params.brick_size);  // brick_size min 0.01
    bool mortar = brick_is_mortar(rel_pos, params.brick_percent);
    vec3 base = mortar ? params.mortar_color : params.brick_color;
    color = params.show == SHOW_REL_POS ? vec4(rel_pos, 0.0, 1.0) : vec4(base * brightness, 1.0);
    mortar_out = mortar ? 1.0 : 0.0;
}
