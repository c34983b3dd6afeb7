#version 450
// Skin (height 0): lit base colour. Shell (height > 0): a strand's cross-section at that height,
// alpha-tested (discard), so the shells need no sorting and write depth.
#include "particles/fur.glsl"
layout(location = 0) in vec3 v_normal;
layout(location = 1) in vec2 v_uv;
layout(location = 2) in float v_height;
layout(location = 0) out vec4 color;
void main() {
    float lambert = max(dot(normalize(v_normal), normalize(vec3(0.5, 0.8, 0.4))), 0.0);
    if (v_height == 0.0) {
        color = vec4(params.skin_color * (0.3 + 0.7 * lambert), 1.0);
        return;
    }
    if (!fur_strand(v_uv * params.cells, v_height)) discard;
    color = vec4(fur_color(v_height, lambert), 1.0);
}
