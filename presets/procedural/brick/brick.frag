#version 450
// Procedural brick, 004_9a40ad89bdfc582a.txt L209-260:
//   rel_pos = position_model.xy / BrickStepSize          brick units
//   if (mod(abs(rel_pos.y), 2.0) > 1.0) rel_pos.x += 0.5  shift odd rows by half a brick
//   rel_pos = fract(rel_pos)                              position within the brick
//   mortar if any(greaterThan(rel_pos, BrickPercent))
// lit with simplistic lighting: brightness = clamp(dot(normal, light), 0, 1).
layout(location = 0) in vec3 a_position_model;
layout(location = 1) in vec3 a_position_world;
layout(location = 2) in vec3 a_normal_world;
layout(location = 0) out vec4 color;
layout(location = 1) out float mortar_out;

void main() {
    vec3 light = normalize(params.light_pos - a_position_world);
    float brightness = clamp(dot(normalize(a_normal_world), light), 0.0, 1.0);
    vec2 rel_pos = a_position_model.xy / params.brick_size;  // brick_size must not be 0 (min 0.01)
    if (mod(abs(rel_pos.y), 2.0) > 1.0) rel_pos.x += 0.5;
    rel_pos = fract(rel_pos);
    bool mortar = any(greaterThan(rel_pos, params.brick_percent));
    vec3 base = mortar ? params.mortar_color : params.brick_color;
    color = params.show == SHOW_REL_POS ? vec4(rel_pos, 0.0, 1.0) : vec4(base * brightness, 1.0);
    mortar_out = mortar ? 1.0 : 0.0;
}
