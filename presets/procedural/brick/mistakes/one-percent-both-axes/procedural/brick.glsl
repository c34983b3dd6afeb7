// EXERCISE — procedural brick (004_9a40ad89bdfc582a.txt L128-260, the fragment shaders
// "brick1" .. "brick3"). This file shadows passes/procedural/brick.glsl for procedural/brick:
// brick.frag includes it and calls the three functions below.
//     passlab run   procedural/brick --exercise presets/procedural/brick/exercise
//     passlab grade procedural/brick --exercise presets/procedural/brick/exercise
// brick_brightness (the notes' simplistic lighting) is done for you; fill in the four TODO
// blocks of brick_rel_pos and brick_is_mortar. `--set show=rel_pos` shows what brick_rel_pos
// returns as red and green, the notes' "brick1" step (L234).
// Pitfalls (L209, L141): BrickStepSize must not be 0 (the param has min 0.01), and the position
// must be the model-space one (brick.frag passes it): world positions make the bricks swim.
#ifndef PASSLAB_PROCEDURAL_BRICK_GLSL
#define PASSLAB_PROCEDURAL_BRICK_GLSL

// Position within its brick, in [0, 1)^2, with the odd rows shifted (L226-232).
vec2 brick_rel_pos(vec2 position_model, vec2 brick_step) {
    // TODO 1: the position in brick units (L226): one brick step (brick + mortar) becomes one
    // unit in x and y, so that brick k spans [k, k + 1].
    vec2 rel_pos = position_model / brick_step;
    // TODO 2: shift every other row by half a brick in x (L228-230). Write the row test as the
    // notes do, mod(|y|, 2) > 1 on the brick-unit y ("this saves conversion to int / mod"), so
    // that your wall matches the reference's.
    if (mod(abs(rel_pos.y), 2.0) > 1.0) rel_pos.x += 0.5;

    // TODO 3: the position within the brick (L232): each component in [0, 1).
    return fract(rel_pos);
}

// Mortar where the position within the brick passes the brick percentage (L251-254, L260).
bool brick_is_mortar(vec2 rel_pos, vec2 brick_percent) {
    // TODO 4: BrickPercent is the fraction of a step that is brick, per axis: x along the row,
    // y across it. A point is mortar when it lies past the brick part in x or in y (L260 writes
    // the test out per component; L251 as one vector comparison).
    return any(greaterThan(rel_pos, vec2(brick_percent.x)));  // (mistake: the x percentage for y too)
}

// L221-224: brightness = clamp(dot(N_world, normalize(LightPos - P_world)), 0, 1).
float brick_brightness(vec3 light_pos_world, vec3 position_world, vec3 normal_world) {
    vec3 light = normalize(light_pos_world - position_world);
    return clamp(dot(normalize(normal_world), light), 0.0, 1.0);
}
#endif
