#version 450
// The picture and its hole (003_cfc3b5b225ddab3d.txt L65-79, "Original image / Masked region /
// Completion result"): photo = a brick wall or a 5x5 tile of random colours repeated (period 5),
// hole = a box or a vertical stripe, known = photo outside the hole (alpha 1) and black with
// alpha 0 inside (what the fill may copy from: the membership check counts alpha > 0 only).
#include "image/bricks.glsl"

layout(location = 0) out vec4 out_photo;
layout(location = 1) out vec4 out_known;
layout(location = 2) out vec4 out_hole;

vec3 periodic_tile(ivec2 p) { return floor(hash_pcg3(vec3(p % 5, 91.0)) * 255.0 + 0.5) / 255.0; }

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 c = params.picture == PICTURE_PERIODIC ? periodic_tile(p) : image_bricks(p, ivec2(12, 6), 5);
    bool hole = params.hole == HOLE_STRIPE ? (p.x >= 26 && p.x < 38)
                                           : (p.x >= 20 && p.x < 44 && p.y >= 22 && p.y < 42);
    out_photo = vec4(c, 1.0);
    out_known = hole ? vec4(0.0) : vec4(c, 1.0);
    out_hole = vec4(hole ? 1.0 : 0.0, 0.0, 0.0, 1.0);
}
