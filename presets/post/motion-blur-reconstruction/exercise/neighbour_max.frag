#version 450
// EXERCISE (2 of 2: neighbour_max.frag) — NeighbourMax, Equation 2 of
// 002_644d46bdce7e5305.txt L1006, with the refinement of its listing (L1089-1118). A pixel can be
// blurred by a moving object in the next tile, so each tile must know the largest velocity that
// can reach it from its 3 x 3 neighbourhood. Check your work with:
//     passlab run   post/motion-blur-reconstruction --exercise presets/post/motion-blur-reconstruction/exercise --set show=neighbourmax
//     passlab grade post/motion-blur-reconstruction --exercise presets/post/motion-blur-reconstruction/exercise
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 neighbourmax;
uniform sampler2D tilemax;

void main() {
    ivec2 tiles = (ivec2(frame.resolution.xy) + params.tile - 1) / params.tile;
    ivec2 here = ivec2(gl_FragCoord.xy);
    vec2 m = vec2(0.0);
    // TODO 2: Equation 2: NeighbourMax[x, y] = vmax over u, v in [-1, 1] of TileMax[x + u, y + v]
    // (the vector of largest length among the 3 x 3 tiles around, this one included); tiles
    // beyond the border are clamped to the edge.
    //
    // TODO 3: the listing's test (L1106-1113): a neighbour at `offset` counts only if its
    // velocity lies along that offset, so that a horizontal streak does not spread into the tiles
    // above and below (or diagonally), which it cannot reach. With p = sign(offset * v)
    // (component-wise), the neighbour counts when |p.x + p.y| equals the offset's length in
    // tiles, |offset.x| + |offset.y| (this tile itself, offset 0, always counts).

    neighbourmax = vec4(m, 0.0, 1.0);
}
