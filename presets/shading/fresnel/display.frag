#version 450
// The sphere, with the three curves plotted along the bottom: exact (white), Schlick (orange),
// spherical Gaussian (cyan), theta from 0 (left) to 90 degrees (right), R from 0 to 1.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
uniform sampler2D hdr;
uniform sampler2D curve_exact;
uniform sampler2D curve_schlick;
uniform sampler2D curve_sg;
void main() {
    vec3 c = texture(hdr, uv).rgb;
    float plot_top = 0.70;
    if (uv.y > plot_top) {
        float y = (1.0 - uv.y) / (1.0 - plot_top);  // 0 at the bottom edge, 1 at the plot top
        float px = 1.5 / ((1.0 - plot_top) * frame.resolution.y);
        c *= 0.3;
        if (abs(texture(curve_exact, vec2(uv.x, 0.5)).r - y) < px) c = vec3(1.0);
        if (abs(texture(curve_schlick, vec2(uv.x, 0.5)).r - y) < px) c = vec3(1.0, 0.55, 0.1);
        if (abs(texture(curve_sg, vec2(uv.x, 0.5)).r - y) < px * 0.6) c = vec3(0.1, 0.9, 1.0);
    }
    color = vec4(c, 1.0);
}
