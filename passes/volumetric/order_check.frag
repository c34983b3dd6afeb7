#version 450
// Test pass: reads the rendered fisheye sky `src` (sky.frag, SKY_PROJECTION fisheye) and writes
// one texel of differences that must all be > 0:
//   x = B - G, y = G - R at the zenith (the image centre): Rayleigh's lambda^-4 makes the
//       zenith blue (002 L2199-2203); with the sun at 45 degrees, zenith B > G > R
//   z = luminance 45 degrees above the horizon towards the sun's azimuth minus the same opposite
//       it. With the sun near the horizon the two directions have mu = +-cos 45 (nearly) and the
//       same path through the air, so Rayleigh (symmetric in mu) nearly cancels and only a Mie
//       phase peaking towards the sun (the code's -2 g mu, L2456) makes z clearly positive.
//       Meaningful with a low sun only: at 45 degrees the "opposite" point is 90 degrees from it.
// The sun must be at azimuth 0 (up on the fisheye).
layout(location = 0) out vec4 color;
uniform sampler2D src;
vec3 at(vec2 q) {   // q: fisheye coordinates, the unit circle = the horizon (sky_view.glsl)
    vec2 size = vec2(textureSize(src, 0));
    vec2 uv = 0.5 + q * 0.5 * min(size.x, size.y) / size;
    return texelFetch(src, ivec2(uv * size), 0).rgb;
}
void main() {
    vec3 z = at(vec2(0.0));
    float lum_sun = dot(at(vec2(0.0, -0.5)), vec3(0.2126, 0.7152, 0.0722));
    float lum_anti = dot(at(vec2(0.0, 0.5)), vec3(0.2126, 0.7152, 0.0722));
    color = vec4(z.b - z.g, z.g - z.r, lum_sun - lum_anti, 1.0);
}
