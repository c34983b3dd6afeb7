// Cameras built in a shader, for passes that look from somewhere other than the view: a light,
// a mirror, an offscreen render. Conventions match the host's (scene/camera.hpp): right-handed
// view space looking down -z, Vulkan clip space (y down, depth 0..1).
#ifndef PASSLAB_CAMERA_GLSL
#define PASSLAB_CAMERA_GLSL

// World -> view for an eye at `eye` looking at `target`, `up` roughly up.
mat4 look_at(vec3 eye, vec3 target, vec3 up) {
    vec3 f = normalize(target - eye), r = normalize(cross(f, up)), u = cross(r, f);
    return mat4(vec4(r.x, u.x, -f.x, 0.0), vec4(r.y, u.y, -f.y, 0.0), vec4(r.z, u.z, -f.z, 0.0),
                vec4(-dot(r, eye), -dot(u, eye), dot(f, eye), 1.0));
}

// View -> clip: vertical field of view in radians, aspect w/h, depth 0 at near and 1 at far.
mat4 perspective(float fovy, float aspect, float near, float far) {
    float t = 1.0 / tan(0.5 * fovy);
    return mat4(t / aspect, 0.0, 0.0, 0.0, 0.0, -t, 0.0, 0.0, 0.0, 0.0, far / (near - far), -1.0, 0.0, 0.0,
                near * far / (near - far), 0.0);
}

// View -> clip, orthographic box [-w/2, w/2] x [-h/2, h/2] x [near, far].
mat4 orthographic(float width, float height, float near, float far) {
    return mat4(2.0 / width, 0.0, 0.0, 0.0, 0.0, -2.0 / height, 0.0, 0.0, 0.0, 0.0, 1.0 / (near - far), 0.0, 0.0, 0.0,
                near / (near - far), 1.0);
}
#endif
