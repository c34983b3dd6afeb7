#version 450
// Lambert with the colour T(p) of the solid texture at the object-space point (solid.glsl):
// the texture belongs to the object and moves with it (object_offset), as carved wood does.
// Evaluated at v_world instead, a moving object would slide through a fixed block of wood
// (the texture "swims"): the case moving-the-object-moves-its-texture.
#include "solid.glsl"
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 2) in vec3 v_object;
layout(location = 0) out vec4 hdr;
void main() {
    vec3 n = normalize(v_normal);
    vec3 albedo = carved_wood(texture_space(v_object));
    float diffuse = max(dot(n, normalize(params.light_dir)), 0.0);
    hdr = vec4(albedo * (diffuse + params.ambient), 1.0);
}
