#version 450
// The picture and the user's marking (003_cfc3b5b225ddab3d.txt L192-202: "building segment marked
// by user" -> "building scaled up, preserving texture"): a brick wall with a tower of small blue
// bricks (x in [26, 38), from y = 10 down), the marked segment. The tower is to become
// `scale` times wider about its centre: the target region T = the scaled segment.
//   photo   the picture (the source of every patch)
//   outside the picture with alpha 0 inside T (what the canvas starts from)
//   region  r = 1 inside T
//   guide   inside T the marked segment stretched (nearest), alpha 1; alpha 0 elsewhere
#include "image/bricks.glsl"

layout(location = 0) out vec4 out_photo;
layout(location = 1) out vec4 out_outside;
layout(location = 2) out vec4 out_region;
layout(location = 3) out vec4 out_guide;

const float kCentre = 32.0;      // the tower's centre column (x = 26 .. 37)
const float kHalf = 6.0;         // its half width

vec3 picture(ivec2 p) {
    bool tower = p.x >= 26 && p.x < 38 && p.y >= 10;
    return tower ? image_bricks(p, ivec2(6, 4), 9).bgr : image_bricks(p, ivec2(12, 6), 5);
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 c = picture(p);
    float half_t = kHalf * params.scale;
    bool in_t = abs(float(p.x) + 0.5 - kCentre) < half_t && p.y >= 10;
    out_photo = vec4(c, 1.0);
    out_outside = in_t ? vec4(0.0) : vec4(c, 1.0);
    out_region = vec4(in_t ? 1.0 : 0.0, 0.0, 0.0, 1.0);
    // the segment's texel under p when the segment is stretched by `scale` about its centre
    ivec2 q = ivec2(floor(kCentre + (float(p.x) + 0.5 - kCentre) / params.scale), p.y);
    out_guide = in_t ? vec4(picture(q), 1.0) : vec4(0.0);
}
