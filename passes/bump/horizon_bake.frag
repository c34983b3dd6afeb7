#version 450
// Horizon map bake (001_fe43b953f362fae7.txt L965-975: "preprocess: compute n horizon values
// per texel"). For n = 8 azimuths phi_k = k pi/4 (k = 0 along +u, 2 along +v) march from the
// texel across the height field and keep the highest elevation angle of the terrain seen:
//     alpha_k = atan( max over t of (h(p + t d_k) - h(p)) * depth / t ),   clamped to >= 0
// h from the alpha of `heights` (bump/heightfield.frag's layout), depth = params.bump_depth:
// the relief's depth in uv units (the same 1/k the normal map was made with, so the shadows
// and the normals describe one relief). t runs over params.horizon_steps steps of one texel.
// Output: alpha_0..3 in horizon_a, alpha_4..7 in horizon_b, radians.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 horizon_a;
layout(location = 1) out vec4 horizon_b;
uniform sampler2D heights;
const float kPi = 3.14159265358979;
void main() {
    vec2 texel = 1.0 / vec2(textureSize(heights, 0));
    float h0 = texture(heights, uv).a;
    float alpha[8];
    for (int k = 0; k < 8; ++k) {
        float phi = float(k) * kPi / 4.0;
        vec2 d = vec2(cos(phi), sin(phi));
        float best = 0.0;   // tan of the elevation; a horizon below the tangent plane counts as 0
        for (int i = 1; i <= params.horizon_steps; ++i) {
            float t = float(i) * texel.x;   // uv distance (square maps)
            best = max(best, (texture(heights, uv + d * t).a - h0) * params.bump_depth / t);
        }
        alpha[k] = atan(best);
    }
    horizon_a = vec4(alpha[0], alpha[1], alpha[2], alpha[3]);
    horizon_b = vec4(alpha[4], alpha[5], alpha[6], alpha[7]);
}
