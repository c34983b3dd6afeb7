#version 450
// The object textured through one of the parametrisations (mapping.glsl), lit by one
// directional light. EXTENT (half-size of the mesh's bounding box, a define per mesh) maps
// the box and planar projections and the cylinder's height to [0, 1].
// Test targets: albedo (the texture colour; alpha 1 at seam pixels, 0.5 elsewhere on the
// object) and dvdh (dv/dy_screen / dy_world/dy_screen = dv per unit height; g = valid).
#include "mapping.glsl"
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 0) out vec4 hdr;
layout(location = 1) out vec4 albedo;
layout(location = 2) out vec2 dvdh;
uniform sampler2D tex_uv_grid;
uniform sampler2D tex_checker;
uniform sampler2D tex_noise;

vec3 lookup(vec2 uv, vec2 dx, vec2 dy) {
    if (params.seam_fix) {
        if (params.image == IMAGE_CHECKER) return textureGrad(tex_checker, uv, dx, dy).rgb;
        if (params.image == IMAGE_NOISE) return textureGrad(tex_noise, uv, dx, dy).rgb;
        return textureGrad(tex_uv_grid, uv, dx, dy).rgb;
    }
    // implicit derivatives (dynamically uniform branch: a param)
    if (params.image == IMAGE_CHECKER) return texture(tex_checker, uv).rgb;
    if (params.image == IMAGE_NOISE) return texture(tex_noise, uv).rgb;
    return texture(tex_uv_grid, uv).rgb;
}

void main() {
    vec3 n = normalize(v_normal);
    vec3 p = v_world;                          // meshes are centred on their bounding box
    vec3 dpx = dFdx(p), dpy = dFdy(p);
    Param m = parametrize(params.mapping, p, EXTENT, n, dpx, dpy);
    vec3 c = lookup(m.uv, m.dx, m.dy);
    float diffuse = max(dot(n, normalize(params.light_dir)), 0.0);
    hdr = vec4(c * (params.ambient + (1.0 - params.ambient) * diffuse), 1.0);
    bool seam = m.u_jump > 0.25;
    albedo = vec4(c, seam ? 1.0 : 0.5);
    float dy_world = dFdy(p.y), dv = dFdy(m.uv.y);
    bool valid = !seam && abs(dy_world) > 0.25 * length(dpy);
    dvdh = valid ? vec2(dv / dy_world, 1.0) : vec2(0.0);
}
