#version 450
// What the preset shows: the culled scene, or one level of the max-Z pyramid (nearest texel, far =
// white).
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 ldr;
uniform sampler2D scene;
uniform sampler2D pyramid;
#include "visibility/hiz.glsl"   // pl_level_size: textureSize(pyramid, k) is wrong on lavapipe
void main() {
    if (params.show == SHOW_PYRAMID) {
        int k = min(params.level, textureQueryLevels(pyramid) - 1);
        ivec2 s = pl_level_size(pyramid, k);
        float z = texelFetch(pyramid, min(ivec2(uv * vec2(s)), s - 1), k).r;
        // Perspective depth crowds near 1: show the eye distance instead (near 0.05, far 100), 0..10 m.
        float d = 0.05 / max(1.0 - z * (99.95 / 100.0), 1e-7);
        ldr = vec4(vec3(min(d / 10.0, 1.0)), 1.0);
        return;
    }
    ldr = texture(scene, uv);
}
