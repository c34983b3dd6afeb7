#version 450
// Lambert: L = albedo * (ambient + max(0, n . l))  (000_c9f7e5de708ecbb3.txt L893-898, diffuse shading).
// The texture is sampled with the image's sampler: trilinear with 16x anisotropy, so the grid
// stays sharp on faces seen at grazing angles instead of blurring to gray.
layout(location = 0) in vec3 v_normal;
layout(location = 1) in vec2 v_uv;
layout(location = 0) out vec4 color;

uniform sampler2D albedo;

void main() {
    vec3 n = normalize(v_normal);
    vec3 l = normalize(params.light_dir);
    vec3 base = texture(albedo, v_uv).rgb;  // albedo is rgba8_srgb: decoded to linear here
    if (params.show_mip) {
        // textureQueryLod gives the level the hardware would pick; tint levels 0..5.
        float lod = textureQueryLod(albedo, v_uv).y;
        const vec3 tint[6] = vec3[](vec3(1, 1, 1), vec3(1, 0.3, 0.3), vec3(0.3, 1, 0.3),
                                    vec3(0.3, 0.3, 1), vec3(1, 1, 0.3), vec3(1, 0.3, 1));
        base *= tint[clamp(int(lod + 0.5), 0, 5)];
    }
    vec3 c = base * (params.ambient + max(0.0, dot(n, l)));
    color = vec4(c, 1.0);
}
