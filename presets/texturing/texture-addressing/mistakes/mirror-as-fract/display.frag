#version 450
// EXERCISE — texture addressing (000_c9f7e5de708ecbb3.txt L1593-1616): do by hand what the
// sampler's address modes do. The reference shader reads eight hardware samplers (repeat,
// mirror, clamp, border; nearest and linear); here every band reads the 4x4 pattern texel by
// texel (texelFetch ignores the sampler), and you map each texel the filter needs into the
// texture, and the grade compares your bands with the hardware's.
//     passlab run   texturing/texture-addressing --exercise presets/texturing/texture-addressing/exercise
//     passlab grade texturing/texture-addressing --exercise presets/texturing/texture-addressing/exercise
// Four bands, top to bottom: repeat, mirror, clamp, border. Across the screen the texture
// coordinate runs over [-(span-1)/2, (span+1)/2], so [0,1] sits in the middle; white lines
// mark u = 0 and u = 1.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
uniform sampler2D pattern;

const int MODE_REPEAT = 0, MODE_MIRROR = 1, MODE_CLAMP = 2, MODE_BORDER = 3;

// The texel with integer index i; outside the texture (an index < 0 or >= its size) the border
// colour, opaque black. This is all the border mode needs: it reads the coordinate as it is.
vec3 fetch(ivec2 i) {
    ivec2 n = textureSize(pattern, 0);
    if (any(lessThan(i, ivec2(0))) || any(greaterThanEqual(i, n))) return vec3(0.0);
    return texelFetch(pattern, i, 0).rgb;
}

// One axis: u is the texture coordinate of the centre of a texel the filter reads, (k + 0.5) / n
// for a whole number k, anywhere on the real line; n is the texture's size in texels along this
// axis. Return the coordinate where the mode reads it: floor(result * n) must be the index of
// the texel the sampler returns (fetch turns an index outside 0..n-1 into the border colour).
float address(int mode, float u, float n) {
    if (mode == MODE_REPEAT) {
        // TODO 1: repeat (L1593-1616): the texture tiles the plane, every copy the same way
        // round; the coordinate keeps only its position inside its copy:
        //     T(u) = T(u - floor(u))
        return u - floor(u);
    }
    if (mode == MODE_MIRROR) {
        // TODO 2: mirror (L1593-1616): the copies alternate, every other one flipped, so the
        // texture meets its mirror image at every whole number:
        //     T(1 + d) = T(1 - d),  T(-d) = T(d),  period 2
        return fract(u);
    }
    if (mode == MODE_CLAMP) {
        // TODO 3: clamp (L1593-1616): outside the texture the edge texels are repeated
        // outwards, T(u > 1) = T(1), T(u < 0) = T(0). "The edge" is the centre of the first
        // and of the last texel, not 0 and 1: a coordinate clamped to [0, 1] is still on the
        // edge of the texture, and floor(1 * n) = n is no texel of it.
        return clamp(u, 0.5 / n, 1.0 - 0.5 / n);
    }
    return u;  // border: the coordinate as it is
}

// The texel whose centre has coordinates c, read through the mode on both axes.
vec3 texel(int mode, vec2 c) {
    vec2 n = vec2(textureSize(pattern, 0));
    vec2 a = vec2(address(mode, c.x, n.x), address(mode, c.y, n.y));
    return fetch(ivec2(floor(a * n)));
}

// Nearest filtering: the texel t falls in (its centre is (floor(t n) + 0.5) / n).
vec3 sample_nearest(int mode, vec2 t) {
    vec2 n = vec2(textureSize(pattern, 0));
    return texel(mode, (floor(t * n) + 0.5) / n);
}

// Bilinear filtering: the four texels whose centres surround t, weighted by the distance to them.
vec3 sample_linear(int mode, vec2 t) {
    vec2 n = vec2(textureSize(pattern, 0));
    vec2 x = t * n - 0.5;
    vec2 i = floor(x), f = x - i;
    vec3 t00 = texel(mode, (i + vec2(0.5, 0.5)) / n), t10 = texel(mode, (i + vec2(1.5, 0.5)) / n);
    vec3 t01 = texel(mode, (i + vec2(0.5, 1.5)) / n), t11 = texel(mode, (i + vec2(1.5, 1.5)) / n);
    return mix(mix(t00, t10, f.x), mix(t01, t11, f.x), f.y);
}

void main() {
    int band = int(uv.y * 4.0);
    float span = params.span;
    vec2 t = vec2(uv.x * span - 0.5 * (span - 1.0), fract(uv.y * 4.0) * span * 0.5 - 0.25 * (span - 2.0));
    bool lin = params.filtering == FILTERING_LINEAR;
    int mode = band == 0 ? MODE_REPEAT : band == 1 ? MODE_MIRROR : band == 2 ? MODE_CLAMP : MODE_BORDER;
    vec3 c = lin ? sample_linear(mode, t) : sample_nearest(mode, t);
    float px = span / frame.resolution.x;
    if (abs(t.x) < px || abs(t.x - 1.0) < px) c = vec3(1.0);
    if (fract(uv.y * 4.0) < 0.01) c = vec3(0.3);
    color = vec4(c, 1.0);
}
