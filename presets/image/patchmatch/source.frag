#version 450
// Bakes the two images of the experiment (003_cfc3b5b225ddab3d.txt L162-168: "reconstruct A
// using patches from B"): B is the brick wall, A is either B shifted by (dx, dy) — the
// shifted-copy test, where the exact answer is known: f(a) = a + (dx, dy) — or another wall
// (other colours and grain, the same brick size), which B's patches can only approximate.
#include "image/bricks.glsl"

layout(location = 0) out vec4 out_a;
layout(location = 1) out vec4 out_b;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    const ivec2 brick = ivec2(16, 8);
    out_b = vec4(image_bricks(p, brick, 1), 1.0);
    if (params.scene == SCENE_SHIFT)
        out_a = vec4(image_bricks(p + ivec2(params.shift), brick, 1), 1.0);   // A(p) = B(p + d)
    else
        out_a = vec4(image_bricks(p + ivec2(5, 3), brick, 2), 1.0);
}
