#version 450
// One texel: x = min |dv/dh| / max |dv/dh| over the valid pixels (1 = constant),
// y = mean |dv/dh| x 2 EXTENT.y (1 for the cylinder: v = (y - y_min) / height),
// z = the largest |seam pixel - mean of its nearest non-seam left and right neighbours| (rgb),
// w = the number of seam pixels compared. At most ~60000 pixels are visited (a stride),
// below lavapipe's silent 65535-iteration loop cut.
layout(location = 0) out vec4 result;
uniform sampler2D albedo;
uniform sampler2D dvdh;
void main() {
    ivec2 size = textureSize(albedo, 0);
    int stride = int(ceil(sqrt(float(size.x * size.y) / 60000.0)));
    float lo = 1e30, hi = 0.0, sum = 0.0, count = 0.0, worst = 0.0, seams = 0.0;
    for (int y = 1; y < size.y - 1; y += stride)
        for (int x = 4; x < size.x - 4; x += stride) {
            vec2 d = texelFetch(dvdh, ivec2(x, y), 0).rg;
            if (d.g > 0.5) {
                lo = min(lo, abs(d.r));
                hi = max(hi, abs(d.r));
                sum += abs(d.r);
                count += 1.0;
            }
            vec4 c = texelFetch(albedo, ivec2(x, y), 0);
            if (c.a < 0.75) continue;
            // nearest non-seam object pixels within 3 to the left and to the right
            vec4 l = vec4(0.0), r = vec4(0.0);
            for (int k = 1; k <= 3 && l.a != 0.5; ++k) l = texelFetch(albedo, ivec2(x - k, y), 0);
            for (int k = 1; k <= 3 && r.a != 0.5; ++k) r = texelFetch(albedo, ivec2(x + k, y), 0);
            if (l.a != 0.5 || r.a != 0.5) continue;
            vec3 dev = abs(c.rgb - 0.5 * (l.rgb + r.rgb));
            worst = max(worst, max(dev.r, max(dev.g, dev.b)));
            seams += 1.0;
        }
    result = vec4(count > 0.0 ? lo / hi : 0.0, count > 0.0 ? sum / count * 2.0 * EXTENT_Y : 0.0, worst, seams);
}
