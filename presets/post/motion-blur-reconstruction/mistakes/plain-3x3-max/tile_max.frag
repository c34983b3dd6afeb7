#version 450
// Equation 1 of 002 L1004: TileMax[x, y] = vmax over the k x k tile of V, "vmax" keeping the
// vector of largest length. One fragment per tile. (002's listing sizes the loop by
// uTexMotionBlurTempTileMax but declares uTexVelocityBuffer, a pitfall it prints as is; here
// the bound is the full-resolution image's own size.)
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 tilemax;
uniform sampler2D vq;

void main() {
    int k = params.tile;
    ivec2 size = ivec2(frame.resolution.xy);
    ivec2 origin = ivec2(gl_FragCoord.xy) * k;
    vec2 m = vec2(0.0);
    float largest = 0.0;
    for (int y = 0; y < k; ++y)
        for (int x = 0; x < k; ++x) {
            vec2 v = texelFetch(vq, min(origin + ivec2(x, y), size - 1), 0).xy;
            if (dot(v, v) > largest) m = v, largest = dot(v, v);
        }
    tilemax = vec4(m, 0.0, 1.0);
}
