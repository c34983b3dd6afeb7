#version 450
// Pull-push, the push (000 L5258-5273, "pull-push hole filling"; Grossman & Dally 1998): level
// l + 1 of the pyramid from level l, each texel the nearest of its 2x2 children that hold a
// point,
//     D_{l+1}(p) = min { D_l(2p + o) : o in {0,1}^2, D_l(2p + o) < 1 },  else 1 (still a hole).
// The minimum, not a mean: an occluder seen through a hole must stay an occluder (a mean would
// mix it with the wall behind and move it to a depth where nothing is).
layout(location = 0) flat in int v_layer;
uniform sampler2DArray src;   // level l (a one-level view)
layout(location = 0) out vec4 o_depth;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy) * 2;
    float d = 1.0;
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) d = min(d, texelFetch(src, ivec3(p + ivec2(i, j), v_layer), 0).r);
    o_depth = vec4(d, 0.0, 0.0, 0.0);
}
