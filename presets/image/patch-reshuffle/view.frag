#version 450
// Left: the picture (the marked tower), centre: the guide (the tower stretched, nearest: blocky,
// bricks twice as wide), right: the reshuffled picture (the tower wider, its bricks at their size).
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
uniform sampler2D photo;
uniform sampler2D outside;
uniform sampler2D guide;
uniform sampler2D canvas;

void main() {
    vec2 px = uv * frame.resolution.xy;
    ivec2 cs = textureSize(canvas, 0);
    float scale = max(floor(min(frame.resolution.x / float(3 * cs.x + 40), frame.resolution.y / float(cs.y + 8))), 1.0);
    vec2 origin = vec2(0.5 * (frame.resolution.x - scale * float(3 * cs.x + 32)), 0.5 * (frame.resolution.y - scale * float(cs.y)));
    vec2 t = (px - origin) / scale;
    color = vec4(0.1, 0.1, 0.12, 1.0);
    for (int k = 0; k < 3; ++k) {
        vec2 local = t - vec2(float(k * (cs.x + 16)), 0.0);
        if (any(lessThan(local, vec2(0.0))) || any(greaterThanEqual(local, vec2(cs)))) continue;
        ivec2 p = ivec2(local);
        vec4 c = k == 0 ? texelFetch(photo, p, 0)
               : k == 1 ? (texelFetch(guide, p, 0).a > 0.0 ? texelFetch(guide, p, 0) : texelFetch(outside, p, 0))
                        : texelFetch(canvas, p, 0);
        color = c.a > 0.0 ? vec4(c.rgb, 1.0) : vec4(0.05, 0.07, 0.2, 1.0);
    }
}
