// The texture matrix and the video frame index, shared by water.frag (the picture) and
// matrix_check.frag (the test's probes).
//     M(t) = T(scroll * t) * T(c) * R(spin * t) * T(-c),     (u', v', 1) = M(t) (u, v, 1)
// (000_c9f7e5de708ecbb3.txt L1620-1624: "texture matrix — can specify an arbitrary 4x4 matrix,
// each frame! Possibilities: moving water or sky"; 2D homogeneous 3x3 here.)
// The offsets are reduced modulo one texture period before they enter M (fract(scroll * t)):
// the repeat address mode makes that invisible, and the coordinates stay small however long
// the lab runs (float precision of u + 10^4 would be ~1e-3 texels).
#ifndef TEXTURE_ANIMATION_GLSL
#define TEXTURE_ANIMATION_GLSL
const float kTwoPi = 6.28318530718;
const vec2 kSpinCentre = vec2(0.5);   // the texture's centre: spin about it, not about (0, 0)

// The animation's clock: the frame time plus the param the tests use to jump a period ahead.
// One definition for the picture and the probes, so the periodicity cases (t against
// t + period, through time_offset) cannot silently compare a render with itself.
float animation_time() { return frame.time + params.time_offset; }

mat3 texture_matrix(float t, vec2 scroll, float spin) {
    vec2 offset = fract(scroll * t);                   // one period of the repeat
    float a = kTwoPi * fract(spin * t);                // spin in turns per second
    const vec2 c = kSpinCentre;
    mat3 to_c = mat3(1, 0, 0, 0, 1, 0, -c.x, -c.y, 1), from_c = mat3(1, 0, 0, 0, 1, 0, c.x, c.y, 1);
    mat3 rot = mat3(cos(a), sin(a), 0, -sin(a), cos(a), 0, 0, 0, 1);
    mat3 move = mat3(1, 0, 0, 0, 1, 0, offset.x, offset.y, 1);
    return move * from_c * rot * to_c;
}

// The video (L1625-1626, "can use video as texture"): layer floor(t * fps) mod n.
int video_frame(float t, float fps, int n) {
    int k = int(floor(t * fps)) % n;
    return k < 0 ? k + n : k;                          // t < 0 (a negative time_offset)
}
#endif
