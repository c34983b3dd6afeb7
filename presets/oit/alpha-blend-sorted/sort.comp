#version 450
// Explicit depth sorting (000_c9f7e5de708ecbb3.txt L4150-4159): "Write sorted order into draw
// buffer" and draw the objects back to front with the over blend ("Blending must be back to front",
// L4135; glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA), L2132). One thread per object slot
// computes its object's rank: the number of objects farther away (larger centre depth; equal
// depths: larger object id first, so the order depends on the objects alone, never on the order the
// application listed them in). Then order[rank] = object: slot 0 of the draw is the farthest.
// The sort is per object (its centre), so it cannot draw the two cases L4156-4157 name:
// "Cyclic overlap" and "Intersecting triangles" (the pinwheel and the crossing pair).
#include "oit/scene.glsl"
#include "submit_order.glsl"
layout(local_size_x = OIT_INSTANCES) in;
layout(std430) writeonly buffer Order { uint object[]; } order;

// The sort key: NDC depth at the quad's centre (oit_depth at the centre is plane.x).
float sort_key(int q) { return oit_quad(q, params.stack).plane.x; }

void main() {
    int slot = int(gl_LocalInvocationID.x);
    int q = submitted_object(slot);           // the application's (unsorted) object list
    if (!params.sorted) { order.object[slot] = uint(q); return; }
    // rank = how many objects are drawn before q (farther, or as far with a
    // larger id); L4142 "Write sorted order into draw buffer", back to front (L4135).
    float kq = sort_key(q);
    int rank = 0;
    for (int o = 0; o < OIT_INSTANCES; ++o) {
        float ko = sort_key(o);
        if (ko > kq || (ko == kq && o > q)) ++rank;
    }
    order.object[rank] = uint(q);
}
