#version 450
// EXERCISE — this file shadows the shared oit/peel.frag for oit/depth-peeling only.
//     passlab run   presets/oit/depth-peeling --exercise presets/oit/depth-peeling/exercise
//     passlab grade presets/oit/depth-peeling --exercise presets/oit/depth-peeling/exercise
// Depth peeling, one layer (Everitt 2001; 000_c9f7e5de708ecbb3.txt L4164-4183): "Each successive
// pass - finds the depth/color for the next nearest fragment on a per-pixel basis", "use a shader
// for comparison with previous layer" (L4170, L4180). The pass renders the transparent scene with
// a fresh depth buffer (cleared to 1, test less, write): the depth test keeps the nearest
// fragment that survives this shader, which rejects
//   - fragments behind the opaque scene (its depth buffer, sampled: the peel depth buffer is not it);
//   - fragments at or in front of the previous layer's depth `prev` (peeled already).
// Layer 0 has no previous layer. Shared by depth-peeling and dual-depth-peeling's test-only check.
#include "oit/scene.glsl"
layout(location = 0) flat in vec4 v_color;
layout(location = 0) out vec4 layer;
uniform sampler2D prev;           // the previous layer's depth (the other half of the ping-pong)
uniform sampler2D opaque_depth;   // the opaque scene's depth

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    float z = gl_FragCoord.z;
    if (z >= texelFetch(opaque_depth, p, 0).r) discard;
    // TODO (peel): "comparison with previous layer" (L4180): keep only what lies behind it.
    // Pitfall: `z < prev` keeps the previous layer itself, which wins the depth test again: every
    // layer would be the first one. Equal depths (coplanar fragments) peel as one layer.
    // Layer 0 (pl_iteration == 0) keeps every fragment; a later layer discards the fragments at or
    // in front of the previous layer's depth, texelFetch(prev, p, 0).r.
    layer = v_color;
}
