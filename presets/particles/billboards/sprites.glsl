// The billboards of this preset: a 7 x 5 grid of sprites from 2 to 10 units in front of the
// orbit target, each drawn as a screen-aligned or an axis-aligned quad (particles/billboard.glsl).
#ifndef BILLBOARDS_SPRITES_GLSL
#define BILLBOARDS_SPRITES_GLSL
#include "particles/billboard.glsl"

#define SPRITES_COLS 7
#define SPRITES_ROWS 5
#define SPRITES (SPRITES_COLS * SPRITES_ROWS)

vec3 sprite_centre(int i) {
    int c = i % SPRITES_COLS, r = i / SPRITES_COLS;
    return vec3((float(c) - 3.0) * 1.1 + 0.3 * float(r & 1), params.size, 1.0 - 2.0 * float(r));
}

// World position of corner `corner` (in [-1, 1]^2) of sprite i, seen from the frame's camera.
vec3 sprite_corner(int i, vec2 corner) {
    vec3 c = sprite_centre(i);
    if (params.mode == MODE_AXIS)
        return pl_billboard_axis(c, corner, params.size, vec3(0, 1, 0), frame.camera_pos.xyz);
    return pl_billboard_screen(c, corner, params.size, frame.inv_view);
}
#endif
