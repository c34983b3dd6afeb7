#version 450
// Pull-push, the pull (000 L5258-5273): from the coarsest level down, a texel of level l that
// holds a point keeps it, a hole takes its parent's (already filled) value,
//     P_l(p) = D_l(p)  if D_l(p) < 1,   else P_{l+1}(p / 2),       P_K = D_K (the 1x1 level),
// so pull-push only fills holes: every texel valid before it is unchanged (the test
// `pullpush-keeps-valid-texels`). With params.pullpush off, P_l = D_l (the holes stay).
layout(location = 0) flat in int v_layer;
uniform sampler2DArray fine;          // D_l, the pushed level (ism_push, one level)
uniform sampler2DArray coarse;        // P_{l+1} (ism_pull one level up) ...
uniform sampler2DArray coarse_push;   // ... or D_{l+1} for the first iteration (l + 1 = K)
layout(location = 0) out vec4 o_depth;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    float d = texelFetch(fine, ivec3(p, v_layer), 0).r;
    if (d >= 1.0 && params.pullpush) {
        ivec3 q = ivec3(p / 2, v_layer);
        d = pl_iteration == 0 ? texelFetch(coarse_push, q, 0).r : texelFetch(coarse, q, 0).r;
    }
    o_depth = vec4(d, 0.0, 0.0, 0.0);
}
