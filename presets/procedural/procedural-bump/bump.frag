#version 450
// Procedural bump mapping, 004_9a40ad89bdfc582a.txt L599: "computing noise in the pixel shader
// and using that for perturbing the surface normal". No texture, no tangents: a height field
// h(p) over the model-space position p (solid texture), and Blinn's perturbed normal written
// with the surface gradient (Blinn 1978; Mikkelsen 2010, "Bump mapping unparametrized
// surfaces on the GPU"):
//     grad_s h = grad h - n (n . grad h)          the part of grad h tangent to the surface
//     n' = normalize(n - grad_s h)                 bumps up where h grows (minus: the normal
//                                                  tilts away from the uphill direction)
//   h = amp * perlin(freq * p)   (pattern noise; perlin = sum (1/2)^i n(2^i x), L315-342)
//   h = amp * sin(k p.x) cos(k p.z),  k = 2 pi freq   (pattern waves)
// grad h is analytic for both: perlin_sum_d differentiates the gradient noise
// (passes/procedural/noise_ext.glsl), one evaluation instead of the six of central
// differences, which only the tests (verify) compute. The model is not moved here
// (model = world); a moved object would need grad h transformed by the normal matrix.
#include "procedural/noise_ext.glsl"
#include "procedural/solid_shading.glsl"
layout(location = 0) in vec3 a_position_model;
layout(location = 1) in vec3 a_position_world;
layout(location = 2) in vec3 a_normal_world;
layout(location = 3) flat in int a_instance;
#ifdef VERIFY
layout(location = 0) out vec2 errors;       // max component |n' - reference|, see main
#else
layout(location = 0) out vec4 color;        // shown: bumped, plain or the normal
layout(location = 1) out vec4 plain_out;    // per-pixel lighting with the mesh normal
layout(location = 2) out vec4 bumped_out;   // per-pixel lighting with n'
layout(location = 3) out vec4 normal_out;   // xyz = n', w = |n'| - 1
#endif

const float kGradStep = 2e-4;  // model units; (k eps)^2 / 6 = 6e-4 relative at 48 cycles/unit (k = 300)
const float kTwoPi = 6.28318530718;

float height(vec3 p) {
    if (params.pattern == PATTERN_WAVES) {
        float k = kTwoPi * params.freq;
        return params.amp * sin(k * p.x) * cos(k * p.z);
    }
    return params.amp * perlin_sum(params.freq * p, params.octaves, 0.5);
}

// grad h in closed form: waves by hand, noise by the chain rule (d/dp n(freq p) = freq n').
vec3 height_gradient(vec3 p) {
    if (params.pattern == PATTERN_WAVES) {
        float k = kTwoPi * params.freq;
        return params.amp * k * vec3(cos(k * p.x) * cos(k * p.z), 0.0, -sin(k * p.x) * sin(k * p.z));
    }
    return params.amp * params.freq * perlin_sum_d(params.freq * p, params.octaves, 0.5).yzw;
}

// The tests' reference for height_gradient: central differences of height(), step kGradStep.
vec3 height_gradient_differences(vec3 p) {
    vec2 e = vec2(kGradStep, 0.0);
    return vec3(height(p + e.xyy) - height(p - e.xyy), height(p + e.yxy) - height(p - e.yxy),
                height(p + e.yyx) - height(p - e.yyx)) / (2.0 * kGradStep);
}

// m: the interpolated (not unit) normal. n' = normalize(n - grad_s h) written on m as
// normalize(m - |m| grad_s h), the same direction, so that with grad h = 0 it is normalize(m),
// the plain normal, bit for bit (normalizing n = m / |m| a second time moves the last bits).
vec3 perturbed_normal(vec3 m, vec3 grad_h) {
    vec3 n = normalize(m);
    vec3 surface_grad = grad_h - n * dot(n, grad_h);
    return normalize(m - length(m) * surface_grad);
}

// The reference for n' that does not use perturbed_normal(): the normal of the displaced
// surface S'(d) = R d + h(R d) d itself (this preset's mesh is a sphere of radius R about the
// origin, d a unit direction), from central differences of S' along two tangents. Blinn's n'
// is its first-order form: exactly, N ~ n (1 + h/R) - grad_s h, so the two differ by about
// |grad_s h| h / R, which the test keeps small.
const float kDirStep = 1e-3;   // radians
vec3 displaced(vec3 d, float radius) { vec3 q = radius * d; return q + height(q) * d; }
vec3 displaced_surface_normal(vec3 p) {
    vec3 d = normalize(p);
    float radius = length(p);
    vec3 t1 = normalize(cross(d, abs(d.y) < 0.9 ? vec3(0, 1, 0) : vec3(1, 0, 0))), t2 = cross(d, t1);
    vec3 a = displaced(normalize(d + kDirStep * t1), radius) - displaced(normalize(d - kDirStep * t1), radius);
    vec3 b = displaced(normalize(d + kDirStep * t2), radius) - displaced(normalize(d - kDirStep * t2), radius);
    vec3 nn = normalize(cross(a, b));
    return dot(nn, d) < 0.0 ? -nn : nn;
}

float max_component(vec3 v) { v = abs(v); return max(v.x, max(v.y, v.z)); }

void main() {
    vec3 n = normalize(a_normal_world);
    vec3 bumped_n = perturbed_normal(a_normal_world, height_gradient(a_position_model));
#ifdef VERIFY
    // The test pass (drawn only with params.verify): x = n' vs n' from central differences of
    // h (checks the analytic grad h); y = n' vs the displaced surface's normal (checks the
    // bump formula itself).
    errors.x = max_component(bumped_n - perturbed_normal(a_normal_world, height_gradient_differences(a_position_model)));
    errors.y = max_component(bumped_n - displaced_surface_normal(a_position_model));
#else
    vec3 l = normalize(params.light_pos - a_position_world);
    vec3 v = normalize(frame.camera_pos.xyz - a_position_world);
    plain_out = vec4(solid_shade(params.albedo, n, l, v, params.specular, params.shininess), 1.0);
    bumped_out = vec4(solid_shade(params.albedo, bumped_n, l, v, params.specular, params.shininess), 1.0);
    normal_out = vec4(bumped_n, length(bumped_n) - 1.0);
    color = params.show == SHOW_PLAIN ? plain_out : params.show == SHOW_NORMAL ? vec4(0.5 + 0.5 * bumped_n, 1.0) : bumped_out;
    // split: the left half of the view lit with the mesh normal, for comparison.
    if (params.split && params.show == SHOW_BUMPED && gl_FragCoord.x < 0.5 * frame.resolution.x) color = plain_out;
#endif
}
