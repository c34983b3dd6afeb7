// The scene of the upsampling experiment, analytic so it can be evaluated at any resolution:
// colour (what is expensive, rendered at 1/4 resolution: 000_c9f7e5de708ecbb3.txt L3262-3268),
// object ID and depth (the cheap full-resolution edge buffer, L3269-3271). Three objects over a
// background: a disc, a box in front of it, a thin ring (thinner than a low-resolution texel in
// places). Colours vary smoothly inside each object, so only ID and depth edges are sharp.
// uv in [0, 1]^2, aspect = width / height. Returns colour; id and depth through out.
#ifndef JBU_SCENE_GLSL
#define JBU_SCENE_GLSL

vec3 jbu_scene(vec2 uv, float aspect, out float id, out float depth) {
    vec2 p = vec2((uv.x - 0.5) * aspect, uv.y - 0.5);
    id = 0.0;
    depth = 1.0;
    vec3 c = mix(vec3(0.16, 0.20, 0.30), vec3(0.45, 0.55, 0.70), uv.y);
    if (length(p - vec2(-0.35, 0.02)) < 0.3) {                     // disc
        id = 1.0; depth = 0.6 + 0.05 * p.x;
        c = vec3(0.95, 0.55, 0.15) * (0.6 + 0.4 * (0.5 - p.y));
    }
    if (abs(length(p - vec2(0.45, -0.05)) - 0.22) < 0.006) {       // thin ring, 1.3 % of the height
        id = 3.0; depth = 0.45;
        c = vec3(0.95, 0.95, 0.85);
    }
    vec2 b = abs(p - vec2(0.0, 0.1)) - vec2(0.2, 0.14);
    if (max(b.x, b.y) < 0.0) {                                      // box in front
        id = 2.0; depth = 0.3 + 0.05 * p.y;
        c = vec3(0.20, 0.70, 0.30) * (0.7 + 0.6 * (p.x + 0.2));
    }
    if (params.constant_guide) { id = 0.0; depth = 0.5; }
    return c;
}
#endif
