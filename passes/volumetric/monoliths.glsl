// The light-shaft scene, in metres: a 30 km ground square and up to 16 monoliths (150 x 1200 x
// 150 m) in a loose 4 x 4 grid 2-6 km in front of the default camera, between it and a low sun at
// azimuth 0 (-z). Shared by the light-shafts and interleaved-sampling presets (params read:
// objects = how many monoliths, 0 = none; ground = draw the ground).
#ifndef PASSLAB_VOLUMETRIC_MONOLITHS_GLSL
#define PASSLAB_VOLUMETRIC_MONOLITHS_GLSL
const int MONOLITHS_MAX = 16;

// Unit cube (-0.5..0.5) -> world, for monolith i; a 4 x 4 grid with a fixed jitter per cell.
mat4 monolith_model(int i) {
    vec2 cell = vec2(i % 4, i / 4);
    vec2 jitter = fract(sin(vec2(i * 7 + 1, i * 13 + 3) * 12.9898) * 43758.5453) - 0.5;
    vec2 xz = vec2(-2400.0, -2000.0) + (cell + 0.6 * jitter) * vec2(1600.0, -1300.0);
    float height = 900.0 + 500.0 * fract(float(i) * 0.618);
    return mat4(vec4(150.0, 0.0, 0.0, 0.0), vec4(0.0, height, 0.0, 0.0), vec4(0.0, 0.0, 150.0, 0.0),
                vec4(xz.x, 0.5 * height, xz.y, 1.0));
}

// The ground: a 30 km square at y = 0 around the monoliths (the plane mesh lies in y = 0 with
// side 1).
mat4 ground_model() {
    return mat4(vec4(30000.0, 0.0, 0.0, 0.0), vec4(0.0, 1.0, 0.0, 0.0), vec4(0.0, 0.0, 30000.0, 0.0),
                vec4(0.0, 0.0, -4000.0, 1.0));
}
#endif
