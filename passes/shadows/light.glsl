// The shadow scene's one light, read from the camera named `light` in [cameras] (docs/format.md
// "[cameras]"): a directional light is an ortho camera (direction = its view's +Z, towards the
// eye), a spot light a perspective one (direction = towards its eye). A point light rendered
// with a cube camera (an array in the cameras block) defines SHADOW_POINT_LIGHT = its position.
#ifndef PASSLAB_SHADOWS_LIGHT_GLSL
#define PASSLAB_SHADOWS_LIGHT_GLSL

// Unit vector from the world point p towards the light.
vec3 shadow_light_dir(vec3 p) {
#ifdef SHADOW_POINT_LIGHT
    return normalize(SHADOW_POINT_LIGHT - p);
#else
    if (cameras.light.clip.w == 1.0) return normalize(cameras.light.inv_view[2].xyz);
    return normalize(cameras.light.position.xyz - p);
#endif
}

#endif
