#version 450
// Tests (one texel, fp32): docs/catalogue.md's "one bright source at p puts flare energy only on
// the line p - centre (angle error < 2 degrees)" for a source anywhere, fitted, not probed.
// Over every texel q of the quarter-resolution flare (texel centres, in texels, which are
// square when the view is), with energy E(q) = r + g + b:
//   centroid  m = sum E q / sum E
//   scatter   S = sum E (q - m)(q - m)^T / sum E
//   the fitted line: through m along the major eigenvector of S, at
//     theta = 0.5 atan2(2 S_xy, S_xx - S_yy)
//   the expected line: through the screen centre c and the source p, at phi = atan2(p - c).
// Writes (|theta - phi| in degrees, modulo 180; the distance of c from the fitted line in
// texels; the rms spread across the fitted line in texels, sqrt of the minor eigenvalue; the
// energy sum E, > 0 so the fit is not of nothing).
layout(location = 0) out vec4 line_fit;
uniform sampler2D flare;
const float kRadToDeg = 57.29577951;
void main() {
    ivec2 n = textureSize(flare, 0);
    float w = 0.0;
    vec2 m = vec2(0.0);
    for (int y = 0; y < n.y; ++y)
        for (int x = 0; x < n.x; ++x) {
            vec3 f = texelFetch(flare, ivec2(x, y), 0).rgb;
            float e = f.r + f.g + f.b;
            w += e;
            m += e * (vec2(x, y) + 0.5);
        }
    m /= max(w, 1e-30);
    float sxx = 0.0, syy = 0.0, sxy = 0.0;
    for (int y = 0; y < n.y; ++y)
        for (int x = 0; x < n.x; ++x) {
            vec3 f = texelFetch(flare, ivec2(x, y), 0).rgb;
            float e = f.r + f.g + f.b;
            vec2 d = vec2(x, y) + 0.5 - m;
            sxx += e * d.x * d.x;
            syy += e * d.y * d.y;
            sxy += e * d.x * d.y;
        }
    sxx /= max(w, 1e-30); syy /= max(w, 1e-30); sxy /= max(w, 1e-30);
    float theta = 0.5 * atan(2.0 * sxy, sxx - syy);
    vec2 c = 0.5 * vec2(n), p = params.light * vec2(n);
    vec2 pc = p - c;
    float phi = atan(pc.y, pc.x);
    float err = abs(theta - phi) * kRadToDeg;
    err = mod(err, 180.0);
    err = min(err, 180.0 - err);
    vec2 dir = vec2(cos(theta), sin(theta));
    vec2 cm = c - m;
    float dist = abs(cm.x * dir.y - cm.y * dir.x);
    // Eigenvalues of S: mean +- sqrt(((sxx - syy) / 2)^2 + sxy^2); the minor one across the line.
    float minor = 0.5 * (sxx + syy) - sqrt(0.25 * (sxx - syy) * (sxx - syy) + sxy * sxy);
    line_fit = vec4(err, dist, sqrt(max(minor, 0.0)), w);
}
