#version 450
// The lookup against its source: for 128 x 64 directions (a latitude-longitude grid over the
// whole sphere, texel centres), the largest colour difference between dp_lookup through the
// two maps and the cube map the maps were baked from.
#include "envmap/dual_paraboloid.glsl"
layout(location = 0) out float diff;
uniform samplerCube env;
uniform sampler2DArray maps;
void main() {
    vec2 q = gl_FragCoord.xy / vec2(128.0, 64.0);
    float phi = 6.2831853 * q.x, theta = 3.14159265 * q.y;
    vec3 d = vec3(sin(theta) * cos(phi), cos(theta), sin(theta) * sin(phi));
    vec3 e = abs(dp_lookup_level0(maps, d).rgb - textureLod(env, d, 0.0).rgb);
    diff = max(e.r, max(e.g, e.b));
}
