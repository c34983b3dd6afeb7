#version 450
// The height field the shading marches through, chosen once (baked again when `heights`
// changes): one sampler in shade.frag keeps its marching loops to one copy each.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 nmap;
uniform sampler2D nmap_tiles;
uniform sampler2D nmap_top;
uniform sampler2D nmap_floor;
void main() {
    nmap = params.heights == HEIGHTS_TOP ? texture(nmap_top, uv) : params.heights == HEIGHTS_FLOOR ? texture(nmap_floor, uv) : texelFetch(nmap_tiles, ivec2(gl_FragCoord.xy), 0);
}
