#version 450
// x: max |coarse - fine| over pixels both cover with n.z > 0.5 (away from the silhouettes);
// y, z: peak brightness (max of r) of coarse and fine; w: (y - z) / z, the peak's relative change.
layout(location = 0) out vec4 stats;
uniform sampler2D coarse;
uniform sampler2D fine;
void main() {
    ivec2 size = textureSize(coarse, 0);
    float worst = 0.0, pc = 0.0, pf = 0.0;
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) {
            vec4 a = texelFetch(coarse, ivec2(x, y), 0), b = texelFetch(fine, ivec2(x, y), 0);
            pc = max(pc, a.r), pf = max(pf, b.r);
            if (a.a > 0.5 && b.a > 0.5) worst = max(worst, length(a.rgb - b.rgb) / sqrt(3.0));
        }
    stats = vec4(worst, pc, pf, abs(pc - pf) / max(pf, 1e-6));
}
