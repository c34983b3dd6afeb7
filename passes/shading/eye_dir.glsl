// Unit direction from a world position towards the eye, for perspective and orthographic
// views alike: an orthographic projection (proj[3][3] = 1) has parallel view rays, all along
// the camera's +z axis, so v is the same everywhere (the shading presets rely on that for
// analytic highlight positions).
#ifndef PASSLAB_EYE_DIR_GLSL
#define PASSLAB_EYE_DIR_GLSL
vec3 eye_dir(vec3 p) {
    return normalize(frame.proj[3][3] == 1.0 ? (frame.inv_view * vec4(0.0, 0.0, 1.0, 0.0)).xyz
                                             : frame.camera_pos.xyz - p);
}
#endif
