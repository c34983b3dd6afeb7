#version 450
// The hatched objects. KIND 0: the floor, 1: a ball, 2: a torus (scene objects); 3: one big
// ball alone (scene ball, the test). The surface coordinates (u, v) of the mesh are scaled by
// REPEAT so strokes keep about the same size on every object (a sphere's u runs round its
// equator, twice as long as v from pole to pole). WRAP (0/1 per axis): which directions close
// on themselves.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec2 uv;
layout(location = 0) out vec3 v_normal;
layout(location = 1) out vec2 v_uv;

void main() {
    vec3 p = position;
    bool visible = params.scene == SCENE_OBJECTS;
#if KIND == 1
    p += vec3(-0.55, 0.5, 0.0);
#elif KIND == 2
    p = vec3(p.x, p.y, p.z) + vec3(0.65, 0.16, 0.25);
#elif KIND == 3
    visible = params.scene == SCENE_BALL;
#endif
    // The stroke tile must repeat a whole number of times round a closed direction, or the
    // strokes break at the mesh's u = 0 / 1 seam: u on the spheres, u and v on the torus
    // (WRAP); open directions (the floor, a sphere's pole-to-pole v) keep the exact repeat.
    vec2 repeats = REPEAT * params.stroke_density;
    repeats = mix(repeats, max(floor(repeats + 0.5), vec2(1.0)), WRAP);
    v_normal = normal;
    v_uv = uv * repeats;
    gl_Position = frame.view_proj * vec4(p, 1.0);
    if (!visible) gl_Position = vec4(0.0, 0.0, -2.0, 1.0);
}
