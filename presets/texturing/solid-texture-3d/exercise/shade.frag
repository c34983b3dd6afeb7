#version 450
// EXERCISE — the solid texture on a moving object: Lambert with the colour T(p) of the solid
// texture (solid.glsl, TODO 1, 2). object.vert moves the mesh by params.object_offset and
// passes both the mesh's own position (v_object) and where it is drawn (v_world).
#include "solid.glsl"
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 2) in vec3 v_object;
layout(location = 0) out vec4 hdr;
void main() {
    vec3 n = normalize(v_normal);
    // TODO 3: the point the texture is evaluated at (L1721-1725, "directly map object space
    // T(x, y, z)"; L1742, carved objects): the wood belongs to the object and moves with it.
    // texture_space() then scales it and shifts it by tex_offset.
    vec3 albedo = carved_wood(texture_space(vec3(0.0)));
    float diffuse = max(dot(n, normalize(params.light_dir)), 0.0);
    hdr = vec4(albedo * (diffuse + params.ambient), 1.0);
}
