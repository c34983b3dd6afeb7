// The shadow family's shared scene (passes/shadows/scene.glsl: ground, box, ball; mesh k of the
// scene buffer = object k) as the ray-traced shadow presets' top level, with a shadow ray's
// payload and stages: visibility = 1 when the miss stage runs (000_c9f7e5de708ecbb3.txt
// L5765-5770: "if ray misses -> not in shadow; skip closest hit shader; use miss shader").
// SHADOW_SCENE_LONE (an expression, default false): only the ball, object 2, is in the scene.
#ifndef PASSLAB_RAYTRACE_SHADOW_SCENE_GLSL
#define PASSLAB_RAYTRACE_SHADOW_SCENE_GLSL

struct RtPayload {
    float lit;  // 0 until the miss stage runs
};

#include "raytrace/stages.glsl"
#include "raytrace/shadow_ray.glsl"
#include "shadows/scene.glsl"
#include "shadows/light.glsl"

#ifndef SHADOW_SCENE_LONE
#define SHADOW_SCENE_LONE false
#endif

int shadow_scene_object(int instance) { return (SHADOW_SCENE_LONE) ? SHADOW_BALL : instance; }
int rt_instance_count() { return (SHADOW_SCENE_LONE) ? 1 : SHADOW_OBJECTS; }
uint rt_instance_mesh(int instance) { return uint(shadow_scene_object(instance)); }
mat4 rt_object_from_world(int instance) { return inverse(shadow_model(shadow_scene_object(instance))); }

void rt_closest_hit(inout RtPayload payload, RtHitInfo hit) {}  // not run: SKIP_CLOSEST_HIT_SHADER
void rt_miss(inout RtPayload payload, RtRay ray) { payload.lit = 1.0; }

// 1 if the light is seen from the surface point p (unit normal n) along the unit direction d.
// A direction below the surface's tangent plane (n.d <= 0) is in the surface's own shadow: no
// ray decides that.
float shadow_scene_visibility(vec3 p, vec3 n, vec3 d) {
    if (dot(n, d) <= 0.0) return 0.0;
    RtPayload payload = RtPayload(0.0);
    rt_trace_ray(shadow_ray(p, n, d), SHADOW_RAY_FLAGS, payload);
    return payload.lit;
}

// The G-buffer's surface at a pixel (shadow_gbuffer.frag): false on the background.
bool shadow_scene_surface(sampler2D gpos, sampler2D gnrm, ivec2 px, out vec3 p, out vec3 n, out int object) {
    vec4 g = texelFetch(gpos, px, 0);
    p = g.xyz;
    n = texelFetch(gnrm, px, 0).xyz;
    object = int(g.w + 0.5) - 1;
    return object >= 0;
}

// Lambert under the sun times the visibility, as the shadow family's shade.frag, gamma-encoded
// for an rgba8 storage image (which cannot be sRGB); the sky on the background.
const float SHADOW_SCENE_AMBIENT = 0.2;  // so shadowed surfaces keep their shape and colour
vec4 shadow_scene_shade(int object, vec3 n, vec3 l, float v) {
    vec3 c = object < 0 ? vec3(0.55, 0.65, 0.8) : shadow_albedo(object) * (SHADOW_SCENE_AMBIENT + (1.0 - SHADOW_SCENE_AMBIENT) * v * max(dot(n, l), 0.0));
    return vec4(pow(c, vec3(1.0 / 2.2)), 1.0);
}

// The shadow family's visibility target: r = visibility (1 on the background), g = 1 on the
// ground, b = 1 on a caster, a = 1 where N.L > 0.1 (the lit side, away from the terminator's
// facets, whose flat triangles may turn away from the light while the interpolated normal faces it).
vec4 shadow_scene_vis(int object, vec3 n, vec3 l, float v) {
    if (object < 0) return vec4(1.0, 0.0, 0.0, 0.0);
    bool ground = object == SHADOW_GROUND;
    return vec4(v, ground ? 1.0 : 0.0, ground ? 0.0 : 1.0, dot(n, l) > 0.1 ? 1.0 : 0.0);
}

#endif
