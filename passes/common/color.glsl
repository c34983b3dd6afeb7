// Colour helpers: exact piecewise sRGB transfer functions (IEC 61966-2-1) and luminance.
#ifndef PASSLAB_COLOR_GLSL
#define PASSLAB_COLOR_GLSL

vec3 srgb_to_linear(vec3 c) {
    return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), step(vec3(0.04045), c));
}

vec3 linear_to_srgb(vec3 c) {
    return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

// Rec. 709 luminance of a linear colour.
float luminance(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }

#endif
