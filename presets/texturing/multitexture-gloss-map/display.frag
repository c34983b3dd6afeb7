#version 450
// Clamp to the display and, with show_maps, the three textures along the bottom.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
uniform sampler2D hdr;
uniform sampler2D diffuse_map;
uniform sampler2D gloss_map;
uniform sampler2D id_map;
void main() {
    vec3 c = clamp(texture(hdr, uv).rgb, 0.0, 1.0);
    float side = 0.22 * frame.resolution.y;                  // thumbnail size in pixels
    vec2 px = vec2(uv.x, 1.0 - uv.y) * frame.resolution.xy;  // from the bottom-left corner
    if (params.show_maps && px.y < side && px.x < 3.0 * side) {
        int k = int(px.x / side);
        vec2 t = vec2(fract(px.x / side), 1.0 - px.y / side);
        c = k == 0 ? texture(diffuse_map, t).rgb : k == 1 ? texture(gloss_map, t).rgb : texture(id_map, t).rgb;
    }
    color = vec4(c, 1.0);
}
