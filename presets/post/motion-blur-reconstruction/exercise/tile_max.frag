#version 450
// EXERCISE (1 of 2: tile_max.frag, then neighbour_max.frag) — the tiles of McGuire et al.'s
// reconstruction filter as 002_644d46bdce7e5305.txt presents it (L1004-1006). The scaled
// velocities V (xy, px per frame) are in `vq`; one fragment of this pass is one k x k tile.
// Fill in TODO 1 here and TODO 2, 3 in neighbour_max.frag, then check your work:
//     passlab run   post/motion-blur-reconstruction --exercise presets/post/motion-blur-reconstruction/exercise --set show=neighbourmax
//     passlab grade post/motion-blur-reconstruction --exercise presets/post/motion-blur-reconstruction/exercise
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 tilemax;
uniform sampler2D vq;

void main() {
    int k = params.tile;
    ivec2 size = ivec2(frame.resolution.xy);
    vec2 m = vec2(0.0);
    // TODO 1: Equation 1 (L1004): TileMax[x, y] = vmax over u, v in [0, k) of V[kx + u, ky + v],
    // where vmax keeps the VECTOR of largest length (not a component-wise max, not a mean).
    // gl_FragCoord.xy is this tile's centre (x + 0.5, y + 0.5); the last tiles may reach past the
    // image's edge (the image size need not be a multiple of k): stay inside it.

    tilemax = vec4(m, 0.0, 1.0);
}
