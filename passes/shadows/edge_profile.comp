#version 450
// Test-only: the preset's visibility (its "method.glsl", the function the view shades with) at
// points along a ground line that leaves the box's shadow across its far edge: from the box's
// footprint centre, away from the light, t = PROFILE_T0 .. PROFILE_T1 (defines, world units).
// Buffer `profile`, one vec4 per point: (visibility, |v * LEVELS - round(v * LEVELS)|, t, 0)
// with LEVELS (define) the number of compare results a kernel averages (16 for a 4 x 4 PCF):
// a `sorted` check says monotone across the edge, a `range` check on field 4 "multiples of 1/16".
layout(local_size_x = 64) in;
#include "shadows/scene.glsl"
#include "shadows/light.glsl"
#include "method.glsl"
layout(std430) writeonly buffer Profile { vec4 s[]; } profile;
void main() {
    uint i = gl_GlobalInvocationID.x, n = uint(profile.s.length());
    if (i >= n) return;
    vec3 l = shadow_light_dir(vec3(0.0));
    vec2 away = -normalize(l.xz);
    float t = PROFILE_T0 + (PROFILE_T1 - PROFILE_T0) * float(i) / float(n - 1u);
    vec3 p = vec3(SHADOW_BOX_AT.x, 0.0, SHADOW_BOX_AT.z) + vec3(away.x, 0.0, away.y) * t;
    float v = shadow_visibility(p, vec3(0.0, 1.0, 0.0), l);
    float levels = float(LEVELS);
    profile.s[i] = vec4(v, abs(v * levels - round(v * levels)), t, 0.0);
}
