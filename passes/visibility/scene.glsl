// The visibility presets' scene: an occluding wall and a grid of boxes behind and beside it,
// drawn as procedural cubes (36 vertices from gl_VertexIndex, no mesh), so a cull pass and a draw
// agree on every object's bounds by construction. Object i < PL_VIS_OBJECTS is a box of the grid;
// the wall is drawn by its own pass.
#ifndef PASSLAB_VIS_SCENE_GLSL
#define PASSLAB_VIS_SCENE_GLSL

#define PL_VIS_COLS 12
#define PL_VIS_ROWS 5
#define PL_VIS_GRID (PL_VIS_COLS * PL_VIS_ROWS)
#define PL_VIS_OBJECTS (PL_VIS_GRID + 1)   // the grid and one box that pierces the wall

struct PlBox { vec3 centre; vec3 half_size; };

// The wall: 3.2 wide, 0.2 thick at z = 0, from y = -0.4 to 1.6 (below the boxes' feet, so their
// rectangles are not cut by its bottom edge when seen from above).
PlBox pl_vis_wall() { return PlBox(vec3(0.0, 0.6, 0.0), vec3(1.6, 1.0, 0.1)); }

// Grid boxes: 12 columns 0.7 apart, 5 rows from z = -1 to -5, heights from a fixed pattern
// (none reaches over the wall's top as seen from the default camera).
PlBox pl_vis_object(int i) {
    // The last box pierces the wall (z from -0.4 to 0.6; the wall's front face is at z = 0.1):
    // its far corners are behind the wall, its near ones in front, so only a test with its
    // NEAREST depth keeps it.
    if (i == PL_VIS_GRID) return PlBox(vec3(0.6, 0.35, 0.1), vec3(0.25, 0.35, 0.5));
    int c = i % PL_VIS_COLS, r = i / PL_VIS_COLS;
    float h = 0.18 + 0.07 * float((c * 7 + r * 3) % 5);
    return PlBox(vec3((float(c) - 5.5) * 0.7, h, -1.0 - float(r)), vec3(0.2, h, 0.2));
}

// Corner v (0..35) of a unit cube's 12 triangles, counter-clockwise seen from outside, with the
// face normal.
void pl_cube_vertex(int v, out vec3 p, out vec3 n) {
    int face = v / 6, k = v % 6;
    const vec2 q[6] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, -1), vec2(1, 1), vec2(-1, 1));
    int axis = face >> 1;
    float s = (face & 1) == 0 ? 1.0 : -1.0;
    vec3 u = axis == 0 ? vec3(0, 1, 0) : axis == 1 ? vec3(0, 0, 1) : vec3(1, 0, 0);
    vec3 w = axis == 0 ? vec3(0, 0, 1) : axis == 1 ? vec3(1, 0, 0) : vec3(0, 1, 0);
    n = s * (axis == 0 ? vec3(1, 0, 0) : axis == 1 ? vec3(0, 1, 0) : vec3(0, 0, 1));
    p = n + q[k].x * u * s + q[k].y * w;   // (u s) x w = n keeps every face counter-clockwise
}

vec3 pl_vis_color(int i) {
    return 0.35 + 0.55 * fract(vec3(0.13, 0.37, 0.71) * float(i + 1) + vec3(0.1, 0.5, 0.3));
}
#endif
