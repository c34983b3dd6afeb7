#version 450
// Equation 2 of 002 L1006: NeighbourMax = vmax of TileMax over the 3 x 3 tiles around, with the
// listing's refinement (002 L1089-1118, the test at L1106-1113): a neighbour counts only if its
// velocity points along the offset to this tile, |sum(sign(offset * v))| == |offset.x| + |offset.y|, so a
// horizontal streak does not spread up and down into tiles it cannot reach.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 neighbourmax;
uniform sampler2D tilemax;

void main() {
    ivec2 tiles = (ivec2(frame.resolution.xy) + params.tile - 1) / params.tile;
    ivec2 here = ivec2(gl_FragCoord.xy);
    vec2 m = vec2(0.0);
    float largest = -1.0;
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x) {
            ivec2 offset = ivec2(x, y);
            vec2 v = texelFetch(tilemax, clamp(here + offset, ivec2(0), tiles - 1), 0).xy;
            if (dot(v, v) <= largest) continue;
            float displacement = float(abs(offset.x) + abs(offset.y));
            vec2 point = sign(vec2(offset) * v);
            if (abs(point.x + point.y) == displacement) m = v, largest = dot(v, v);
        }
    neighbourmax = vec4(m, 0.0, 1.0);
}
