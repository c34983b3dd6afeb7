// Dual-paraboloid shadow maps (000_c9f7e5de708ecbb3.txt L4730-4739): "paraboloid maps directions
// inside one half-sphere to a disc; arrange two such discs inside a shadow map; can be generated
// in two passes (instead of six)". The mapping is the environment map's (envmap/dual_paraboloid.glsl,
// 001_fe43b953f362fae7.txt L194-224): for a unit direction u of the hemisphere u.z >= 0 (layer 0)
// or u.z <= 0 (layer 1),
//     (s, t) = u.xy / (1 + |u.z|)          rho = |(s, t)| <= 1 inside the disc, 1 on the rim
// Here the paraboloids' axis is world +Y (dp_light_frame), so the seam between the two discs is
// the horizontal plane through the light: it runs round the room's walls at the light's height.
//
// Rendering: the vertex shader does the warp (no camera can: it is not a projection), so straight
// edges become curves only at the vertices: meshes must be finely tessellated (the room is 24 x 24
// segments per surface; the box's six 2-triangle faces are the visible exception). The depth
// written is the linear distance (|d| - near) / (far - near), and gl_ClipDistance keeps each
// hemisphere plus DP_MARGIN of the other, so the bilinear compare at the rim reads real depths.
#ifndef PASSLAB_SHADOWS_PARABOLOID_GLSL
#define PASSLAB_SHADOWS_PARABOLOID_GLSL
#include "envmap/dual_paraboloid.glsl"
#include "shadows/shadow_map.glsl"

const float DP_MARGIN = 0.08;   // cos of the angle past the rim still rendered into each disc (~4.6 degrees)

// World direction -> the paraboloids' frame (a rotation: x -> x, y -> z, z -> -y).
vec3 dp_light_frame(vec3 d) { return vec3(d.x, -d.z, d.y); }

float dp_depth(float distance_to_light, float near, float far) { return (distance_to_light - near) / (far - near); }

// Clip position of world point p in map `layer` (0: upper hemisphere, 1: lower), and its clip
// distance (>= 0 inside the hemisphere plus the margin).
vec4 dp_shadow_clip(vec3 p, vec3 light, int layer, float near, float far, out float clip_distance) {
    vec3 r = dp_light_frame(p - light);
    float len = length(r);
    vec3 u = r / len;
    clip_distance = (layer == 0 ? u.z : -u.z) + DP_MARGIN;
    vec2 st = dp_coord(u, layer);
    // uv = (0.5 + 0.5 s, 0.5 - 0.5 t) (dp_uv) is NDC (s, -t).
    return vec4(st.x, -st.y, dp_depth(len, near, far), 1.0);
}

// Visibility of p (normal n, unit l towards the light) from the two discs: the hemisphere of
// d = p - light picks the layer; the point is moved towards the light by the shared bias, in
// texels of the map (a texel spans up to 4 / size radians, at the disc's centre).
float dp_visibility(sampler2DArrayShadow maps, vec3 light, float near, float far, vec3 p, vec3 n, vec3 l,
                    float bias_constant, float bias_slope) {
    float texel = 4.0 * distance(p, light) / float(textureSize(maps, 0).x);
    vec3 q = p + shadow_bias_world(texel, dot(n, l), bias_constant, bias_slope) * l;
    vec3 r = dp_light_frame(q - light);
    float len = length(r);
    vec3 u = r / len;
    int layer = u.z >= 0.0 ? 0 : 1;
    vec2 uv = dp_uv(dp_coord(u, layer));
    return texture(maps, vec4(uv, float(layer), dp_depth(len, near, far)));
}
#endif
