#version 450
// The farthest base-mesh depth in each 8 x 8 pixel tile (for the occlusion cull in prism.geom).
// A pixel's nearest relief hit is no farther than its base-mesh depth (a ray that reaches the
// triangle, w = 0, has hit, h >= 0), so a prism whose nearest corner lies behind the farthest
// base depth of every tile its outline touches cannot win a pixel: prism.geom drops it.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 occluder_tiles;
uniform sampler2D occluders;   // the base mesh's depth (pass occluders_*), 1 = background
const int kTile = 8;           // pixels per tile side; prism.geom's kTile
void main() {
    ivec2 size = textureSize(occluders, 0), corner = ivec2(gl_FragCoord.xy) * kTile;
    float farthest = 0.0;
    for (int y = 0; y < kTile; ++y)
        for (int x = 0; x < kTile; ++x)
            farthest = max(farthest, texelFetch(occluders, min(corner + ivec2(x, y), size - 1), 0).x);
    occluder_tiles = vec4(farthest);
}
