#version 450
// Left: the source, centre: the source tiled naively (seams, L24-33 "naive tiling"), right: the
// synthesised texture (unknown texels dark blue while it grows), all at the same texel scale.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
uniform sampler2D src;
uniform sampler2D canvas;

void main() {
    vec2 px = uv * frame.resolution.xy;
    ivec2 cs = textureSize(canvas, 0), ss = textureSize(src, 0);
    float scale = floor(min(frame.resolution.x / float(3 * cs.x + 40), frame.resolution.y / float(cs.y + 8)));
    scale = max(scale, 1.0);
    vec2 origin = vec2(0.5 * (frame.resolution.x - scale * float(3 * cs.x + 32)), 0.5 * (frame.resolution.y - scale * float(cs.y)));
    vec2 t = (px - origin) / scale;
    color = vec4(0.1, 0.1, 0.12, 1.0);
    for (int k = 0; k < 3; ++k) {
        vec2 local = t - vec2(float(k * (cs.x + 16)), 0.0);
        if (any(lessThan(local, vec2(0.0))) || any(greaterThanEqual(local, vec2(cs)))) continue;
        ivec2 p = ivec2(local);
        if (k == 0) { if (all(lessThan(p, ss))) color = vec4(texelFetch(src, p, 0).rgb, 1.0); }
        else if (k == 1) color = vec4(texelFetch(src, p % ss, 0).rgb, 1.0);
        else {
            vec4 c = texelFetch(canvas, p, 0);
            color = c.a > 0.0 ? vec4(c.rgb, 1.0) : vec4(0.05, 0.07, 0.2, 1.0);
        }
    }
}
