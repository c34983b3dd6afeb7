// Test scenes for the post-process anti-aliasing presets (aa/mlaa, aa/fxaa-smaa): images that a
// renderer with one sample per pixel would produce, each with the coverage-weighted colour it
// should have had (the reference). All positions are in pixels ((0, 0) = the top-left corner of
// the top-left pixel), so slopes in pixels per pixel hold at every view size.
//
//   0 shapes:    passes/aa/shapes.glsl's turned square and slivers, point-sampled at the pixel
//                centre (as rasterisation does); reference: 8 x 8 samples per pixel.
//   1 staircase: a half-plane under the line y = h/2 + offset + slope (x - w/2) (line = (slope,
//                offset), pixels); reference: the exact area of the half-plane inside the pixel
//                (closed form, below).
//   2 bars:      axis-aligned bars on whole pixel boundaries, running across the whole view:
//                straight edges with no step; the reference equals the image.
//   3 gradient:  smooth colour waves (neighbours differ by at most 0.033, below any sensible
//                edge threshold): edge-free; the reference equals the image.
//   4 checker:   shapes.glsl's fine checker: texture detail finer than a pixel.
// Presets pass their enum (same order) as SCENE.
#ifndef PASSLAB_AA_POST_SCENE_GLSL
#define PASSLAB_AA_POST_SCENE_GLSL
#include "aa/shapes.glsl"

const int kAaShapes = 0, kAaStaircase = 1, kAaBars = 2, kAaGradient = 3, kAaChecker = 4;
const int kRefSamples = 8;        // reference samples per axis for the shapes

// The staircase line's height at x (pixels; y grows downwards); line = (slope, offset).
float stair_line(float x, vec2 line, vec2 size) { return size.y * 0.5 + line.y + line.x * (x - size.x * 0.5); }

// F(u) = integral of clamp(t, 0, 1) dt from 0 to u: the antiderivative that makes the pixel
// coverage of a half-plane exact.
float clamp_integral(float u) { return u <= 0.0 ? 0.0 : (u < 1.0 ? 0.5 * u * u : u - 0.5); }

// Exact fraction of pixel px (integer corner) below the line y = L(x) = a + s x:
//   cov = integral over x in [i, i+1] of clamp(j + 1 - L(x), 0, 1) dx
//       = (F(j + 1 - L(i)) - F(j + 1 - L(i + 1))) / s      (s != 0), clamp(j + 1 - L) for s = 0.
float stair_coverage(ivec2 px, vec2 line, vec2 size) {
    float u0 = float(px.y) + 1.0 - stair_line(float(px.x), line, size);
    float u1 = float(px.y) + 1.0 - stair_line(float(px.x) + 1.0, line, size);
    if (abs(line.x) < 1e-6) return clamp(u0, 0.0, 1.0);
    return (clamp_integral(u0) - clamp_integral(u1)) / line.x;
}

vec3 aa_scene_sample(int scene, vec2 p, vec2 line, vec2 size) {
    if (scene == kAaStaircase) return vec3(p.y > stair_line(p.x, line, size) ? 1.0 : 0.0);
    if (scene == kAaBars) {
        ivec2 q = ivec2(floor(p / 8.0));  // bars 8 px wide: vertical on the left, horizontal on the right
        if (p.x < size.x * 0.5) return (q.x % 2 == 0) ? vec3(0.9, 0.8, 0.3) : vec3(0.1, 0.15, 0.3);
        return (q.y % 3 == 0) ? vec3(0.2, 0.7, 0.9) : vec3(0.05);
    }
    if (scene == kAaGradient) {  // smooth waves: at most 0.3 / 9 = 0.033 between neighbours
        float w = 0.3 * sin(p.x / 9.0) * sin(p.y / 13.0 + 0.5);
        return vec3(0.5 + w, 0.45 + 0.5 * w, 0.5 - 0.4 * w);
    }
    if (scene == kAaChecker) return shape_texture(p / size);
    return shape_color_at(0, p / size, vec2(0.0));
}

// The one-sample-per-pixel image: the scene at the pixel centre.
vec3 aa_scene_color(int scene, ivec2 px, vec2 line, vec2 size) { return aa_scene_sample(scene, vec2(px) + 0.5, line, size); }

// What the pixel should be: its coverage-weighted colour. The shapes' and the checker's
// 64-sample reference is slow on a CPU rasteriser (shapes.glsl walks 8 triangles per sample;
// post_scene.frag draws the shapes through aa_shapes_reference below, which sets them up once):
// with supersample = false they return the one-sample colour instead (no reference).
vec3 aa_scene_reference(int scene, ivec2 px, vec2 line, vec2 size, bool supersample) {
    if (scene == kAaStaircase) return vec3(stair_coverage(px, line, size));
    if (!supersample || (scene != kAaShapes && scene != kAaChecker)) return aa_scene_color(scene, px, line, size);
    vec3 sum = vec3(0.0);
    for (int k = 0; k < kRefSamples * kRefSamples; ++k) {
        vec2 o = (vec2(k % kRefSamples, k / kRefSamples) + 0.5) / float(kRefSamples);
        sum += aa_scene_sample(scene, vec2(px) + o, line, size);
    }
    return sum / float(kRefSamples * kRefSamples);
}
// The shapes scene with its triangles evaluated once per pixel (shapes.glsl's shape_triangles:
// shape_vertex's cos/sin per vertex would otherwise run per sample): the same colours as
// aa_scene_sample / aa_scene_reference for kAaShapes bit for bit, at a fraction of the cost.
vec3 aa_shapes_sample(const vec2 tri[kShapeTriangles * 3], const bool solid[kShapeTriangles], vec2 p, vec2 size) {
    return shape_color_in(0, tri, solid, p / size);
}
vec3 aa_shapes_reference(const vec2 tri[kShapeTriangles * 3], const bool solid[kShapeTriangles], ivec2 px, vec2 size, bool supersample) {
    if (!supersample) return aa_shapes_sample(tri, solid, vec2(px) + 0.5, size);
    vec3 sum = vec3(0.0);
    for (int k = 0; k < kRefSamples * kRefSamples; ++k) {
        vec2 o = (vec2(k % kRefSamples, k / kRefSamples) + 0.5) / float(kRefSamples);
        sum += aa_shapes_sample(tri, solid, vec2(px) + o, size);
    }
    return sum / float(kRefSamples * kRefSamples);
}
#endif
