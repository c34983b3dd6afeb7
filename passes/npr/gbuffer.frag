#version 450
// G-buffer write: view-space normal (w = 1 marks geometry) and 1 / view depth. The reciprocal,
// like the hardware z-buffer's value, is an affine function of screen position on any plane,
// so second differences vanish on planes and image-space edge operators see only creases and
// silhouettes (linear depth on a tilted plane is not affine on screen under perspective).
layout(location = 0) in vec3 v_normal;
layout(location = 1) in float v_depth;
layout(location = 0) out vec4 normal;
layout(location = 1) out float inv_depth;
void main() {
    vec3 n = normalize(v_normal);
    normal = vec4(gl_FrontFacing ? n : -n, 1.0);  // the floor is two-sided
    inv_depth = 1.0 / v_depth;
}
