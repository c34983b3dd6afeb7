#version 450
// Left: the samples (holes dark blue), right: after pull-push.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
uniform sampler2D original;
uniform sampler2D filled;

void main() {
    vec2 px = uv * frame.resolution.xy;
    ivec2 size = textureSize(original, 0);
    float scale = max(floor(min(frame.resolution.x / float(2 * size.x + 24), frame.resolution.y / float(size.y + 8))), 1.0);
    vec2 origin = 0.5 * (frame.resolution.xy - scale * vec2(2 * size.x + 16, size.y));
    vec2 t = (px - origin) / scale;
    color = vec4(0.1, 0.1, 0.12, 1.0);
    for (int k = 0; k < 2; ++k) {
        vec2 local = t - vec2(float(k * (size.x + 16)), 0.0);
        if (any(lessThan(local, vec2(0.0))) || any(greaterThanEqual(local, vec2(size)))) continue;
        vec4 c = k == 0 ? texelFetch(original, ivec2(local), 0) : texelFetch(filled, ivec2(local), 0);
        color = c.a > 0.0 ? vec4(c.rgb, 1.0) : vec4(0.05, 0.07, 0.2, 1.0);
    }
}
