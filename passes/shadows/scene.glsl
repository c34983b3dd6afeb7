// The shared shadow scene (docs/catalogue.md 3.11 "Shared harness"): a ground plane, two closed
// casters, one light. Every shadow preset draws these objects with these placements, so their
// visibility images compare pixel for pixel.
//
//   object 0  ground: mesh { generator = "plane", size = 6 } at y = 0 (the receiver)
//   object 1  box:    mesh { generator = "cube", size = 1 }, turned 25 degrees about +Y, resting on
//                     the ground (its base touches y = 0: the contact line Peter Panning detaches)
//   object 2  ball:   mesh { generator = "sphere", radius = 0.5 }, floating at height 1.1
//
// Casters are closed manifolds (cube, sphere), as stencil shadow volumes need.
#ifndef PASSLAB_SHADOWS_SCENE_GLSL
#define PASSLAB_SHADOWS_SCENE_GLSL

#define SHADOW_GROUND 0
#define SHADOW_BOX 1
#define SHADOW_BALL 2
#define SHADOW_OBJECTS 3

const float SHADOW_BOX_TURN = 0.436332313;   // 25 degrees: box edges not aligned with map texels
const vec3 SHADOW_BOX_AT = vec3(-0.8, 0.5, 0.2);
const vec3 SHADOW_BALL_AT = vec3(0.9, 1.1, -0.3);

// World from object (column-major, as GLSL matrices are).
mat4 shadow_model(int object) {
    if (object == SHADOW_BOX) {
        float c = cos(SHADOW_BOX_TURN), s = sin(SHADOW_BOX_TURN);
        return mat4(vec4(c, 0, -s, 0), vec4(0, 1, 0, 0), vec4(s, 0, c, 0), vec4(SHADOW_BOX_AT, 1));
    }
    if (object == SHADOW_BALL) return mat4(vec4(1, 0, 0, 0), vec4(0, 1, 0, 0), vec4(0, 0, 1, 0), vec4(SHADOW_BALL_AT, 1));
    return mat4(1.0);
}

// Base colour per object (linear).
vec3 shadow_albedo(int object) {
    if (object == SHADOW_BOX) return vec3(0.75, 0.35, 0.2);
    if (object == SHADOW_BALL) return vec3(0.25, 0.45, 0.8);
    return vec3(0.7);
}

#endif
