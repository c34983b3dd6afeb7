#version 450
// Distance fog as a post-process (000_c9f7e5de708ecbb3.txt L2953-3017):
//   c = f c_s + (1 - f) c_f
//   linear  f = (d_end - d) / (d_end - d_start)    clamped to [0, 1] (the document does not)
//   exp     f = exp(-d_f d)
//   exp2    f = exp(-(d_f d)^2)
// d is the distance from the camera (L3012-3013, listing lines 14-15: length(camera.position - p)), here recovered from
// the depth buffer: the pixel's NDC point through the inverse projection is its view-space
// position, whose length is d. (The listing's uniform c_d is never used; we leave it out.)
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 fogged;
layout(location = 1) out float factor;
uniform sampler2D color;
uniform sampler2D depth;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    float z = texelFetch(depth, p, 0).r;
    vec4 view = frame.inv_proj * vec4(uv * 2.0 - 1.0, z, 1.0);
    float d = length(view.xyz / view.w);
    float f = params.mode == MODE_LINEAR ? clamp((params.end - d) / max(params.end - params.start, 1e-6), 0.0, 1.0)
              : params.mode == MODE_EXP  ? exp(-params.density * d)
                                         : exp(-params.density * d * d);
    vec3 cs = texelFetch(color, p, 0).rgb;
    fogged = vec4(f * cs + (1.0 - f) * params.fog_color, 1.0);
    factor = f;
}
