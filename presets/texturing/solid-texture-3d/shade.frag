#version 450
// Lambert with the colour T(p) of the solid texture at the object-space point (solid.glsl).
#include "solid.glsl"
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 0) out vec4 hdr;
void main() {
    vec3 n = normalize(v_normal);
    vec3 albedo = carved_wood(texture_space(v_world));   // the mesh is drawn at the origin
    float diffuse = max(dot(n, normalize(params.light_dir)), 0.0);
    hdr = vec4(albedo * (diffuse + params.ambient), 1.0);
}
