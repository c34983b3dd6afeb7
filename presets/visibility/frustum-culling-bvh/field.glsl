// The scene: a 16 x 16 field of boxes, 3 units apart, and its BVH, an implicit quadtree: level L
// (0..4) has 4^L nodes, node (x, y) of level L bounds the grid cells [x, x+1) * 2^(4-L) (and
// the same in y); level 4's nodes are the boxes. Nodes are numbered level by level:
// index = (4^L - 1) / 3 + y * 2^L + x, 341 in all.
#include "visibility/scene.glsl"    // PlBox, pl_cube_vertex
#define FIELD 16
#define FIELD_LEVELS 5
#define FIELD_NODES 341
#define FIELD_MAX_HEIGHT 1.4

PlBox field_box(int i) {
    int c = i % FIELD, r = i / FIELD;
    float h = 0.3 + 0.25 * float((c * 5 + r * 3) % 5);   // at most 1.3 tall (< FIELD_MAX_HEIGHT)
    return PlBox(vec3((float(c) - 7.5) * 3.0, h * 0.5, (float(r) - 7.5) * 3.0), vec3(0.6, h * 0.5, 0.6));
}

int field_node_index(int level, ivec2 xy) { return ((1 << (2 * level)) - 1) / 3 + xy.y * (1 << level) + xy.x; }

// The node's box: a leaf's is its object's; an inner node's holds all its cells' boxes (centres
// +- 0.6 in x and z, floor to the tallest possible box), so it contains its children's.
void field_node_bounds(int level, ivec2 xy, out vec3 lo, out vec3 hi) {
    if (level == FIELD_LEVELS - 1) {
        PlBox b = field_box(xy.y * FIELD + xy.x);
        lo = b.centre - b.half_size; hi = b.centre + b.half_size;
        return;
    }
    int span = FIELD >> level;
    vec2 c0 = (vec2(xy * span) - 7.5) * 3.0, c1 = (vec2(xy * span + span - 1) - 7.5) * 3.0;
    lo = vec3(c0.x - 0.6, 0.0, c0.y - 0.6);
    hi = vec3(c1.x + 0.6, FIELD_MAX_HEIGHT, c1.y + 0.6);
}
