// The nearest-neighbour field of PatchMatch (003_cfc3b5b225ddab3d.txt L120-125: f: A -> R^2,
// f(a) = b, the centre of a's nearest patch in B), stored in an rgba32f texel:
// xy = b (absolute texel of B, integer-valued floats: exact), z = d(a, b), w = unused (0).
// Offsets f(a) - a are what the view colours (L141-145).
#ifndef PASSLAB_IMAGE_NNF_GLSL
#define PASSLAB_IMAGE_NNF_GLSL

vec4 nnf_encode(ivec2 b, float d) { return vec4(vec2(b), d, 0.0); }
ivec2 nnf_target(vec4 t) { return ivec2(t.xy); }
float nnf_distance(vec4 t) { return t.z; }

// L141-145: "Saturation = magnitude of match offset (gray indicates matching patch in B is at
// same pixel location), Hue = direction of offset; offset X = red-cyan axis, offset Y =
// blue-yellow axis". Grey 0.5 plus the unit direction along those two opponent axes, scaled by
// |offset| / max_len (1 at max_len and beyond).
vec3 nnf_color(vec2 offset, float max_len) {
    float len = length(offset);
    if (len == 0.0) return vec3(0.5);
    vec2 dir = offset / len;
    float sat = min(len / max_len, 1.0);
    const vec3 red_cyan = vec3(0.5, -0.5, -0.5);     // +x towards red, -x towards cyan
    const vec3 blue_yellow = vec3(-0.5, -0.5, 0.5);  // +y towards blue, -y towards yellow
    return clamp(vec3(0.5) + sat * (dir.x * red_cyan + dir.y * blue_yellow), 0.0, 1.0);
}
#endif
