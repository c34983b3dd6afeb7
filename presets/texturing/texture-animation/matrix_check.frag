#version 450
// The texture matrix and the video index at the current time t, against closed forms
// (tests; 4 x 1 texels, rgba32f):
//   x = 0: |M(t) c - (c + fract(s t))|           the spin centre c only moves with the scroll
//   x = 1: |M(t) (c + (r, 0)) - (c + fract(s t) + r (cos a, sin a))|, a = 2 pi spin t, r = 1/4:
//          a point a quarter period from the centre turns about it by a
//   x = 2: M(t) (0, 0) with spin 0 = the scroll offset fract(s t) itself (the test probes the
//          numbers: periods per second, not texels or radians)
//   x = 3: the video frame index floor(t fps) mod 8
//   x = 4: |M(t) (c + (0, r)) - (c + fract(s t) + r (-sin a, cos a))|: the rotation's second
//          column (x = 1 sees only the first)
// c is the texture's centre written out, not kSpinCentre: a check that shares the constant it
// checks cannot see it change.
#include "animation.glsl"
layout(location = 0) out vec4 result;
void main() {
    float t = animation_time();
    vec2 offset = fract(params.scroll * t);
    float spin = params.mode == MODE_ROTATE ? params.spin : 0.0;
    mat3 m = texture_matrix(t, params.scroll, spin);
    const vec2 c = vec2(0.5);
    const float r = 0.25;
    int i = int(gl_FragCoord.x);
    if (i == 0) {
        result = vec4(abs((m * vec3(c, 1.0)).xy - (c + offset)), 0.0, 1.0);
    } else if (i == 1) {
        float a = kTwoPi * spin * t;
        result = vec4(abs((m * vec3(c + vec2(r, 0.0), 1.0)).xy - (c + offset + r * vec2(cos(a), sin(a)))), 0.0, 1.0);
    } else if (i == 2) {
        result = vec4((texture_matrix(t, params.scroll, 0.0) * vec3(0.0, 0.0, 1.0)).xy, 0.0, 1.0);
    } else if (i == 3) {
        result = vec4(float(video_frame(t, params.fps, 8)), 0.0, 0.0, 1.0);
    } else {
        float a = kTwoPi * spin * t;
        result = vec4(abs((m * vec3(c + vec2(0.0, r), 1.0)).xy - (c + offset + r * vec2(-sin(a), cos(a)))), 0.0, 1.0);
    }
}
