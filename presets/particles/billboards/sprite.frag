#version 450
// A round sprite with an alpha test (discard outside the inscribed disc), so sprites need no
// sorting and the depth test resolves their overlaps. The pattern's vertical bar shows the
// quad's up axis. Every covered fragment is counted per sprite (coverage), before the depth test
// (no early_fragment_tests), so a sprite's count is its projected disc's area in pixels.
layout(location = 0) in vec2 corner;
layout(location = 1) flat in int sprite;
layout(location = 0) out vec4 color;
layout(std430) buffer Coverage { uint pixels[]; } coverage;
void main() {
    float r2 = dot(corner, corner);
    if (r2 > 1.0) discard;
    atomicAdd(coverage.pixels[sprite], 1u);
    vec3 base = 0.45 + 0.45 * cos(6.2831853 * (vec3(0.0, 0.33, 0.67) + float(sprite) * 0.137));
    float bar = step(abs(corner.x), 0.12) * step(corner.y, 0.75);          // up axis marker
    float ring = smoothstep(0.8, 0.86, sqrt(r2));
    color = vec4(mix(base * (1.0 - 0.45 * r2), vec3(1.0), max(bar * 0.8, ring * 0.6)), 1.0);
}
