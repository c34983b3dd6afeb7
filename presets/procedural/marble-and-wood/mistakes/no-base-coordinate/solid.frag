#version 450
// EXERCISE — marble and wood as solid (3D) textures, evaluated at the model-space position.
// This file shadows the preset's solid.frag; turbulence() is TODO 1 in procedural/noise_ext.glsl
// next to it. Fill in TODO 2-4, then check your work against the reference:
//     passlab run   procedural/marble-and-wood --exercise presets/procedural/marble-and-wood/exercise
//     passlab grade procedural/marble-and-wood --exercise presets/procedural/marble-and-wood/exercise
// `--set material=wood` or `marble` shows one teapot alone.
//
// Wood, 004_9a40ad89bdfc582a.txt L599-602 (printed):
//     g = a * perlin(x, y, z),   grain = g - int(g)
// plus, optionally, the concentric rings of 000_c9f7e5de708ecbb3.txt L1746-1756 (bands of
// x^2 + y^2: light brown, dark brown, ...): g = a * (perlin(p) + rings * |p.xz|), the tree's
// axis along the model's y. Deviation, stated: 000 bands the squared radius (rings crowding
// outwards); |p.xz| keeps the rings one width apart, like yearly growth. The colour is mix(wood_light, wood_dark, grain).
// Pitfall: int() truncates toward zero, so where g < 0 (gradient noise is signed) the printed
// g - int(g) lies in (-1, 0], not [0, 1), and the bands run backwards across g = 0. We use
// g - floor(g) (= fract(g), in [0, 1)); grain_op = int_printed shows the printed form.
//
// Marble, Perlin's vase of 1985 (004 L585-598; the notes show the picture, not the formula;
// this is the form of Perlin's paper "An image synthesizer"): stripes along x bent by
// turbulence,
//     v = 0.5 + 0.5 * sin(stripes * x + a * turbulence(p)),   colour = mix(vein, base, v^kVeinSharpness)
// perlin() and turbulence() are the fractal sums of L315-342 in passes/procedural/noise_ext.glsl.
#include "procedural/noise_ext.glsl"
#include "procedural/rigid.glsl"
#include "procedural/solid_shading.glsl"
layout(location = 0) in vec3 a_position_model;
layout(location = 1) in vec3 a_position_world;
layout(location = 2) in vec3 a_normal_world;
layout(location = 3) flat in int a_instance;
layout(location = 0) out vec4 color;
#ifndef CARRIED
layout(location = 1) out float grain_out;   // wood: grain; marble: v
layout(location = 2) out vec4 albedo_out;
#endif

const float kVeinSharpness = 0.25;  // v^0.25: wide light base, thin dark veins where v -> 0

void main() {
    vec3 p = params.space == SPACE_OBJECT ? a_position_model : a_position_world;
    bool wood = params.material == MATERIAL_WOOD || (params.material == MATERIAL_BOTH && a_instance == 1);
    vec3 q = params.noise_freq * p;
    float field;
    vec3 albedo;
    if (wood) {
        // TODO 2: the wood's g (004 L599-602 with the rings of 000 L1746-1756): a times the sum
        // of perlin_sum(q, octaves, 0.5) and the ring term rings * |p.xz| (the distance from the
        // tree's axis, the model's y). Both terms are scaled by a: with a = 0, g must be 0.
        float g = params.a * (perlin_sum(q, params.octaves, 0.5) + params.rings * length(p.xz));
        // TODO 3: the grain, the fractional part of g, in [0, 1) for every g, negative ones too
        // (the printed g - int(g), kept below as grain_op = int_printed, is not: see Pitfall).
        float grain = g - floor(g);
        field = params.grain_op == GRAIN_OP_FRACT ? grain : g - float(int(g));
        albedo = mix(params.wood_light, params.wood_dark, field);
    } else {
        // TODO 4: Perlin's marble: stripes along model x, their phase bent by turbulence,
        //     v = 0.5 + 0.5 * sin(stripes * x + a * turbulence(q, octaves)).
        // With a = 0 it must be the plain stripes; with stripes = 0 the turbulence alone.
        field = 0.5 + 0.5 * sin(params.a * turbulence(q, params.octaves));   // MISTAKE: the stripes' base coordinate x left out
        albedo = mix(params.marble_vein, params.marble_base, pow(field, kVeinSharpness));
    }

    // The light and the eye, moved with the object when the camera rides along (solid.vert).
    vec3 light = params.light_pos, eye = frame.camera_pos.xyz;
#ifdef CARRIED
    RigidMotion m = rigid_motion(MOTION);
    vec3 centre = instance_centre(a_instance);
    light = rigid_apply(m, centre, light);
    eye = rigid_apply(m, centre, eye);
#endif
    vec3 n = normalize(a_normal_world);
    vec3 l = normalize(light - a_position_world), v = normalize(eye - a_position_world);
    color = vec4(solid_shade(albedo, n, l, v, params.specular, params.shininess), 1.0);
#ifndef CARRIED
    grain_out = field;
    albedo_out = vec4(albedo, 1.0);
#endif
}
