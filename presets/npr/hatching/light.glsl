// The hatching presets' light: a direction from azimuth (about +y, from +z) and elevation.
#ifndef HATCHING_LIGHT_GLSL
#define HATCHING_LIGHT_GLSL
vec3 light_direction() {
    float az = radians(params.light_azimuth), el = radians(params.light_elevation);
    return vec3(cos(el) * sin(az), sin(el), cos(el) * cos(az));
}
#endif
