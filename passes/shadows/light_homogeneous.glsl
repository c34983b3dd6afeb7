// The shared scene's light (camera `light`, see light.glsl) as a homogeneous point L = (l, w), the
// form projective shadow techniques need: w = 1 a point light at l (a perspective camera's eye),
// w = 0 a directional light, l the direction towards it (an ortho camera's view +Z). Used by the
// planar projection matrix (planar-projected) and the shadow-volume extrusion
// (stencil-shadow-volumes), where "the direction from the light through p" is w p - l.
#ifndef PASSLAB_SHADOWS_LIGHT_HOMOGENEOUS_GLSL
#define PASSLAB_SHADOWS_LIGHT_HOMOGENEOUS_GLSL
vec4 shadow_light_homogeneous() {
    if (cameras.light.clip.w == 1.0) return vec4(normalize(cameras.light.inv_view[2].xyz), 0.0);
    return vec4(cameras.light.position.xyz, 1.0);
}
#endif
