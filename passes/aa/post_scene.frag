#version 450
// Renders a test scene of passes/aa/post_scene.glsl with one sample per pixel (`color`) and its
// coverage-weighted reference (`reference`). SCENE: the scene (an int expression, e.g.
// params.scene); LINE: the staircase's (slope, offset) in pixels (a vec2 expression);
// SUPERSAMPLE: a bool expression, whether the shapes and checker get their 8 x 8 reference
// (slow: only when a view or test needs it). JITTER_PX (vec2 expression, pixels, default 0)
// moves the one sample per pixel (temporal methods); the reference stays unjittered.
#include "aa/post_scene.glsl"
#ifndef LINE
#define LINE vec2(0.25, 0.37)
#endif
#ifndef JITTER_PX
#define JITTER_PX vec2(0.0)
#endif
#ifndef SUPERSAMPLE
#define SUPERSAMPLE true
#endif
layout(location = 0) out vec4 color;
layout(location = 1) out vec4 reference;
void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    if ((SCENE) == kAaShapes) {  // the same values, the triangles set up once per pixel
        vec2 tri[kShapeTriangles * 3];
        bool solid[kShapeTriangles];
        shape_triangles(0, vec2(0.0), tri, solid);
        color = vec4(aa_shapes_sample(tri, solid, vec2(px) + 0.5 + (JITTER_PX), frame.resolution.xy), 1.0);
        reference = vec4(aa_shapes_reference(tri, solid, px, frame.resolution.xy, SUPERSAMPLE), 1.0);
        return;
    }
    color = vec4(aa_scene_sample(SCENE, vec2(px) + 0.5 + (JITTER_PX), LINE, frame.resolution.xy), 1.0);
    reference = vec4(aa_scene_reference(SCENE, px, LINE, frame.resolution.xy, SUPERSAMPLE), 1.0);
}
