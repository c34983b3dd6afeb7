// EXERCISE — this file shadows passes/shadows/omni_cube.glsl for shadows/omni-cube-shadows only.
//     passlab run   presets/shadows/omni-cube-shadows --exercise presets/shadows/omni-cube-shadows/exercise
//     passlab grade presets/shadows/omni-cube-shadows --exercise presets/shadows/omni-cube-shadows/exercise
// As shipped the reference depth is 0 and the lookup direction is fixed: nothing is shadowed.
// Omnidirectional shadow map in a cube (000_c9f7e5de708ecbb3.txt L4721-4727: "shadow maps limited
// to spot-light ... use six shadow maps for omni-directional light source. Expensive!"): six 90
// degree depth maps rendered from the point light, one per cube face (a cube camera, repeat = 6),
// looked up with the direction from the light.
//
// What the reference depth is: face i stored the PERSPECTIVE depth of its own projection, a
// function of the distance along that face's axis, z = max(|d.x|, |d.y|, |d.z|) for d = p - light
// (the major axis selects the face, Vulkan "Cube Map Face Selection"), not of the Euclidean
// distance |d|. Comparing |d| (or its depth) is the classic bug: |d| > z off the face centre, so
// the compare fails increasingly towards the face edges and corners (acne along every seam).
//     depth(z) = (proj * (0, 0, -z, 1)).z / w          (the cube camera's projection)
// A samplerCubeShadow with compare = "less_equal" and linear filtering returns the bilinear
// blend of the four (ref <= texel) results, seamless across faces (Vulkan always filters cube
// maps across face edges).
#ifndef PASSLAB_SHADOWS_OMNI_CUBE_GLSL
#define PASSLAB_SHADOWS_OMNI_CUBE_GLSL
#include "shadows/shadow_map.glsl"

float omni_cube_depth(mat4 face_proj, vec3 d) {
    // TODO 1: the depth face i stored for the point at d = p - light: its distance along the
    // face's own axis, z = max(|d.x|, |d.y|, |d.z|) (the major axis selects the face), through the
    // face's projection: (face_proj * (0, 0, -z, 1)).z / w.
    return 0.0;
}

// Visibility of p (normal n, unit l towards the light at light_pos) from the cube map. The
// point is first moved towards the light by the shared constant + slope-scale bias, in texels of
// the face: a face texel at axis distance z spans 2 z / size (90 degrees).
float omni_cube_visibility(samplerCubeShadow map, mat4 face_proj, vec3 light_pos, vec3 p, vec3 n, vec3 l,
                           float bias_constant, float bias_slope) {
    vec3 d = p - light_pos;
    float z = max(abs(d.x), max(abs(d.y), abs(d.z)));
    float texel = 2.0 * z / float(textureSize(map, 0).x);
    vec3 q = p + shadow_bias_world(texel, dot(n, l), bias_constant, bias_slope) * l - light_pos;
    // TODO 2 (000_c9f7e5de708ecbb3.txt L4721-4727): look the cube up with the direction FROM the
    // light to the (biased) point, q, and compare at omni_cube_depth(face_proj, q).
    return texture(map, vec4(vec3(0.0, 1.0, 0.0), 0.0));
}
#endif
