#version 450
// Shading pass of the shared shadow scene: Lambert under the one light, times the visibility the
// preset's method computes. The preset supplies "method.glsl" (looked up in its folder) with
//     float shadow_visibility(vec3 p, vec3 n, vec3 l);   // 1 lit, 0 shadowed
// Targets (in this order): 0 colour; 1 `vis`, the visibility debug target the tests read:
//     r = visibility (1 lit, 0 shadowed; 1 on the background), g = 1 on the ground (receiver),
//     b = 1 on a caster, a = 1 where there is geometry;
// 2 `world`: xyz = world position, w = object + 1 (0 = background), for reference passes;
// 3, only when the pass defines SHADOW_DEBUG_OUT: the method's own debug vec4, shadow_debug()
// (declared by method.glsl; called after shadow_visibility). With SHADOW_TINT defined the
// colour is multiplied by the method's shadow_tint() (a debug view, e.g. cascades coloured).
#include "shadows/scene.glsl"
#include "shadows/light.glsl"
#include "method.glsl"

#ifndef SHADOW_AMBIENT
#define SHADOW_AMBIENT 0.2   // so shadowed surfaces keep their shape and colour
#endif

layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 0) out vec4 color;
layout(location = 1) out vec4 vis;
layout(location = 2) out vec4 world;
#ifdef SHADOW_DEBUG_OUT
layout(location = 3) out vec4 debug;
#endif
void main() {
    vec3 n = normalize(v_normal);
    vec3 l = shadow_light_dir(v_world);
    float n_dot_l = dot(n, l);
    // A face turned away from the light is in its own shadow: no lookup decides that.
    float v = n_dot_l > 0.0 ? shadow_visibility(v_world, n, l) : 0.0;
    vec3 albedo = shadow_albedo(OBJECT);
    color = vec4(albedo * (SHADOW_AMBIENT + (1.0 - SHADOW_AMBIENT) * v * max(n_dot_l, 0.0)), 1.0);
#ifdef SHADOW_TINT
    color.rgb *= shadow_tint();
#endif
    bool ground = OBJECT == SHADOW_GROUND;
    vis = vec4(v, ground ? 1.0 : 0.0, ground ? 0.0 : 1.0, 1.0);
    world = vec4(v_world, float(OBJECT + 1));
#ifdef SHADOW_DEBUG_OUT
    debug = shadow_debug();
#endif
}
