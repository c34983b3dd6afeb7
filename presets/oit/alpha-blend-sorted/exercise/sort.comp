#version 450
// EXERCISE — this file shadows the preset's sort.comp for oit/alpha-blend-sorted only.
//     passlab run   presets/oit/alpha-blend-sorted --exercise presets/oit/alpha-blend-sorted/exercise
//     passlab grade presets/oit/alpha-blend-sorted --exercise presets/oit/alpha-blend-sorted/exercise
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
    // TODO (sort): rank = how many objects are drawn before q (farther, or as far with a
    // larger id); L4142 "Write sorted order into draw buffer", back to front (L4135).
    //   rank(q) = #{ o in 0..OIT_INSTANCES-1 : sort_key(o) > sort_key(q) or (equal keys and o > q) }
    // so the farthest object gets rank 0 and is drawn first. Ties by object id, never by slot.
    int rank = slot;   // as shipped: the list's order, unsorted
    order.object[rank] = uint(q);
}
