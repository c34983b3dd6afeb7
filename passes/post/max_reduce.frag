#version 450
// One step of a max-Z (hierarchical-Z) pyramid: level i+1 texel p = max of level i texels
// 2p .. 2p+1. `src` is bound to level i alone (bind view mip = "iteration"), so its lod 0 and
// textureSize are level i's. For a min-Z pyramid replace max by min (and start m at 1). Levels halve with floor (Vulkan's mip sizes), so an odd side drops its last row/column:
// the last texel of the next level also takes it (3 texels along that side), which keeps the
// pyramid conservative (every level-0 texel is under some texel of every level).
layout(location = 0) out float maxz;
uniform sampler2D src;
void main() {
    ivec2 s = textureSize(src, 0);
    ivec2 p = ivec2(gl_FragCoord.xy) * 2;
    ivec2 e = min(p + 1 + ivec2(equal(p + 3, s)), s - 1);
    float m = 0.0;
    for (int y = p.y; y <= e.y; ++y)
        for (int x = p.x; x <= e.x; ++x) m = max(m, texelFetch(src, ivec2(x, y), 0).r);
    maxz = m;
}
