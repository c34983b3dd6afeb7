#version 450
// Left: the 32 x 32 histogram, density 1 (uniform) mid grey, above red, below blue, scaled by
// params.contrast. Right: the scatter plot of the first points.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
uniform sampler2D density;
uniform sampler2D scatter;
void main() {
    bool left = uv.x < 0.5;
    vec2 q = vec2(fract(uv.x * 2.0), uv.y);
    if (left) {
        float t = clamp((texture(density, q).r - 1.0) * params.contrast, -1.0, 1.0);
        vec3 mid = vec3(0.35);
        color = vec4(t > 0.0 ? mix(mid, vec3(1.0, 0.25, 0.1), t) : mix(mid, vec3(0.1, 0.3, 1.0), -t), 1.0);
        // faint cell borders: the grid is the test's
        vec2 f = fract(q * 32.0);
        if (min(f.x, f.y) < 0.04) color.rgb *= 0.8;
    } else {
        float h = texture(scatter, q).r;
        color = vec4(vec3(1.0 - exp(-h * 0.7)), 1.0);
    }
}
