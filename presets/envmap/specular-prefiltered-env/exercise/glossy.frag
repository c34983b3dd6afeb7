#version 450
// EXERCISE — a glossy (Phong) object lit by the prefiltered environment: the specular integral
// over the hemisphere is one lookup P(R) of the prefiltered map (001_fe43b953f362fae7.txt
// L333-341, "R as lookup"; L251-260 for R), plus a constant base colour params.diffuse (no
// diffuse lighting: see envmap/irradiance-env for that). TODO 1 and 2 are in
// exercise/prefilter.frag.
// view_reflection(v_world, v_normal) (passes/envmap/reflect.glsl) returns R = V - 2 (N.V) N in
// world space, the space of both cube maps. lookup = source: the unfiltered map, a perfect mirror.
#include "envmap/reflect.glsl"
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 0) out vec4 hdr;
uniform samplerCube prefiltered;
uniform samplerCube env;
void main() {
    // TODO 3: the direction the lobe was centred on when the map was made (L340), then the
    // lookup in `prefiltered` (or in `env` when params.lookup == LOOKUP_SOURCE), and the colour
    // specular * P + diffuse.
    vec3 spec = vec3(0.0);
    hdr = vec4(params.specular * spec + params.diffuse, 1.0);
}
