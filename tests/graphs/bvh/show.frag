#version 450
// A picture of the BVH trace for the live lab: a colour per instance, darker with distance;
// misses dark blue.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
uniform sampler2D hits;

void main() {
    vec4 h = texelFetch(hits, ivec2(uv * vec2(textureSize(hits, 0))), 0);
    const vec3 palette[5] = vec3[](vec3(0.9, 0.5, 0.2), vec3(0.9, 0.8, 0.3), vec3(0.6, 0.6, 0.6), vec3(0.3, 0.7, 0.9),
                                   vec3(0.5, 0.9, 0.5));
    if (h.x < 0.0) color = vec4(0.05, 0.05, 0.2, 1.0);
    else color = vec4(palette[int(h.x) % 5] * exp(-0.15 * h.y), 1.0);
}
