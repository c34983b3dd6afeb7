#version 450
// A glossy (Phong) object lit by the prefiltered environment: the specular integral over the
// hemisphere is the lookup P(R) at the reflection vector R = V - 2 (N.V) N (001_fe43b953f362fae7.txt
// L333-341, L251-260), plus a constant base colour params.diffuse (no diffuse lighting: see
// envmap/irradiance-env for that). lookup = source: the unfiltered map, a perfect mirror.
#include "envmap/reflect.glsl"
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 0) out vec4 hdr;
uniform samplerCube prefiltered;
uniform samplerCube env;
void main() {
    vec3 R = normalize(v_normal);
    vec3 spec = params.lookup == LOOKUP_SOURCE ? texture(env, R).rgb : texture(prefiltered, R).rgb;
    hdr = vec4(params.specular * spec + params.diffuse, 1.0);
}
