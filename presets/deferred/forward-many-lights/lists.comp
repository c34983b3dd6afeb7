#version 450
// The application's per-object light lists, computed each frame (003 L683-700; there by the
// CPU, here by one compute thread per object): a light joins an object's list when its sphere
// meets the object's conservative bound — the ball's bounding sphere, the floor's square.
// The list is padded with kNoLight to 64 entries (the batch shaders read up to their size),
// and a 64-bit mask per object serves the per-light passes (the per-light object lists).
#include "deferred/lights.glsl"
#include "deferred/objects.glsl"
#include "object_lists.glsl"
layout(local_size_x = 65) in;
layout(std430) writeonly buffer object_lights { uint list_words[]; };
layout(std430) writeonly buffer object_masks { uint mask_words[]; };
void main() {
    int o = int(gl_GlobalInvocationID.x);
    if (o >= kObjects) return;
    uint base = uint(o * kListWords), n = 0u, mask[2] = uint[2](0u, 0u);
    for (int i = 0; i < params.lights; ++i) {
        PointLight l = point_light(i, frame.time);
        bool meets;
        if (o == 0) {  // the floor: the square |x|, |z| <= 8 at y = 0 against the sphere
            vec3 nearest = vec3(clamp(l.position.x, -kFloorHalf, kFloorHalf), 0.0, clamp(l.position.z, -kFloorHalf, kFloorHalf));
            meets = distance(nearest, l.position) <= l.radius;
        } else {       // a ball: sphere against sphere
            SceneBall b = scene_ball(o - 1);
            meets = distance(b.centre, l.position) <= l.radius + kBallMeshRadius * b.scale;
        }
        if (!meets) continue;
        list_words[base + 1u + n++] = uint(i);
        mask[i / 32] |= 1u << uint(i % 32);
    }
    list_words[base] = n;
    for (uint k = n; k < uint(kMaxLights); ++k) list_words[base + 1u + k] = kNoLight;
    mask_words[2 * o] = mask[0];
    mask_words[2 * o + 1] = mask[1];
}
