// Procedural brick, shared by presets/procedural/brick and presets/procedural/brick-noisy.
// 004_9a40ad89bdfc582a.txt L209-260 (the fragment shader "brick1" .. "brick3"):
//   rel_pos = position_model.xy / BrickStepSize           position in brick units
//   if (mod(abs(rel_pos.y), 2.0) > 1.0) rel_pos.x += 0.5   shift odd rows by half a brick
//   rel_pos = fract(rel_pos)                               position within the brick
//   mortar if any(greaterThan(rel_pos, BrickPercent))      (L251, L260: x > P.x || y > P.y)
// lit with the notes' simplistic lighting: brightness = clamp(dot(normal, light), 0, 1).
// Pitfalls (L209, L141): BrickStepSize must not be 0 (the presets' params have min 0.01),
// and the position must be the model-space one: world positions make the bricks swim.
#ifndef PASSLAB_PROCEDURAL_BRICK_GLSL
#define PASSLAB_PROCEDURAL_BRICK_GLSL

// Position within its brick, in [0, 1)^2, with the odd rows shifted (L226-232).
vec2 brick_rel_pos(vec2 position_model, vec2 brick_step) {
    vec2 rel_pos = position_model / brick_step;
    // "this saves conversion to int / mod" (L229). The notes' abs() mirrors the rows at y = 0:
    // rows -1 and 0 are both unshifted (GLSL's mod is floored, so without abs they would
    // alternate); kept as the notes write it, the goldens of brick and brick-noisy record it.
    if (mod(abs(rel_pos.y), 2.0) > 1.0) rel_pos.x += 0.5;
    return fract(rel_pos);
}

// Mortar where the position within the brick passes the brick percentage (L251-254).
bool brick_is_mortar(vec2 rel_pos, vec2 brick_percent) {
    return any(greaterThan(rel_pos, brick_percent));
}

// L221-224: brightness = clamp(dot(N_world, normalize(LightPos - P_world)), 0, 1).
float brick_brightness(vec3 light_pos_world, vec3 position_world, vec3 normal_world) {
    vec3 light = normalize(light_pos_world - position_world);
    return clamp(dot(normalize(normal_world), light), 0.0, 1.0);
}
#endif
