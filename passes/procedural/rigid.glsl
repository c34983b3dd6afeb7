// A rigid motion for the solid-texture presets (marble-and-wood, procedural-bump): the object
// turns by t * kRigidAngle about kRigidAxis through its own centre and moves by t * kRigidShift.
// Solid textures read the model-space position (004_9a40ad89bdfc582a.txt L128-200), so such a
// motion must carry the texture along; reading world positions instead makes it swim.
#ifndef PASSLAB_PROCEDURAL_RIGID_GLSL
#define PASSLAB_PROCEDURAL_RIGID_GLSL

const vec3 kRigidAxis = vec3(0.33333333, 0.66666667, 0.66666667);  // unit: (1, 2, 2) / 3
const float kRigidAngle = 2.0943951;                               // 120 degrees at t = 1
const vec3 kRigidShift = vec3(0.4, -0.2, 0.3);                     // world units at t = 1

struct RigidMotion { mat3 rotation; vec3 shift; };

// Rodrigues: R = cos(a) I + sin(a) [k]x + (1 - cos(a)) k k^T.
RigidMotion rigid_motion(float t) {
    float a = t * kRigidAngle, c = cos(a), s = sin(a);
    vec3 k = kRigidAxis;
    mat3 kx = mat3(0.0, k.z, -k.y, -k.z, 0.0, k.x, k.y, -k.x, 0.0);  // columns of [k]x
    return RigidMotion(c * mat3(1.0) + s * kx + (1.0 - c) * outerProduct(k, k), t * kRigidShift);
}

// x' = centre + R (x - centre) + shift, for a point given in world units.
vec3 rigid_apply(RigidMotion m, vec3 centre, vec3 x) { return centre + m.rotation * (x - centre) + m.shift; }

// Where instance i of the object stands: side by side along x, INSTANCE_SPACING apart (a define,
// 0 = all at the origin), centred on the origin for two instances.
#ifndef INSTANCE_SPACING
#define INSTANCE_SPACING 0.0
#endif
vec3 instance_centre(int i) { return vec3((INSTANCE_SPACING) * (float(i) - 0.5), 0.0, 0.0); }
#endif
