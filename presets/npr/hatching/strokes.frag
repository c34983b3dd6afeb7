#version 450
// The stroke texture (bake = true), "created from brush strokes" (000 L3231) as a threshold map:
// kStrokes tapered strokes are laid one after another into a tile that repeats in (u, v); a
// texel stores the index of the first stroke covering it (kStrokes where none does). Shading
// inks a texel once the strokes up to its index are needed for the tone (coverage.frag turns
// the index into the tile's coverage at that stroke), so a darker tone shows every stroke of a
// lighter one plus more (nested, like tonal art maps, Praun et al. 2001). The first half of the
// strokes runs along u, the next 30% along v (cross-hatching for the mid tones), the rest
// diagonally.
#include "common/hash.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out float stroke_index;
const int kStrokes = STROKES;
const float kWidth = 0.01;          // half-width at the middle of a stroke (tile units), x [0.5, 1.5)
const float kLengthMin = 0.12, kLengthMax = 0.3;
const float kJitter = 0.08;         // radians of random tilt off the stroke direction

void main() {
    int first = kStrokes;
    for (int i = 0; i < kStrokes && first == kStrokes; ++i) {
        vec3 h = hash_pcg3(vec3(float(i), 31.0, 7.0));
        vec3 g = hash_pcg3(vec3(float(i), 3.0, 97.0));
        float t = float(i) / float(kStrokes);
        float angle = (t < 0.5 ? 0.0 : t < 0.8 ? 1.5707963 : 0.7853982) + kJitter * (2.0 * g.x - 1.0);
        vec2 dir = vec2(cos(angle), sin(angle));
        vec2 d = fract(uv - h.xy + 0.5) - 0.5;  // offset to the stroke's centre, wrapped: the tile repeats
        float along = dot(d, dir), across = dot(d, vec2(-dir.y, dir.x));
        float half_len = 0.5 * mix(kLengthMin, kLengthMax, h.z);
        float x = along / half_len;
        if (abs(x) < 1.0 && abs(across) < kWidth * (0.5 + g.y) * sqrt(1.0 - x * x))
            first = i;
    }
    stroke_index = float(first);
}
