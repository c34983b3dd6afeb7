#version 450
// The reconstruction filter (002 L1123-1195, unoptimised listing): around pixel X, S taps Y
// along the neighbourhood's dominant velocity vn, each weighted by
//   alpha_Y = f cone(|X-Y|, |v_Y|) + b cone(|X-Y|, |v_X|) + 2 cylinder(|X-Y|, |v_Y|) cylinder(|X-Y|, |v_X|)
//   f = softDepthCompare(z_X, z_Y): Y is in front and blurs over X;  b = the reverse
//   cone(d, v) = clamp(1 - d / |v|, 0, 1)
//   cylinder(d, v) = 1 - smoothstep(0.95 |v|, 1.05 |v|, d)
//   softDepthCompare(za, zb) = clamp(1 - (za - zb) / SOFT_Z_EXTENT, 0, 1)
// plus X itself with weight 1/|vn|. Pixels with |vn| < 0.5125 px keep their colour (early out).
// Depths are the view depth stored with V (002 uses -linearised depth; same ordering).
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 result;
uniform sampler2D color;
uniform sampler2D vq;
uniform sampler2D neighbourmax;

const float kEarlyOut = 0.5125;  // px, 002 L1170

float cone(float d, float v) { return clamp(1.0 - d / max(v, 1e-7), 0.0, 1.0); }
float cylinder(float d, float v) { return 1.0 - smoothstep(0.95 * v, 1.05 * v, d); }
// Arguments are view depths (larger = farther); 002 compares negated depths, z = -depth.
float soft_depth_compare(float za, float zb) { return clamp(1.0 - (za - zb) / params.soft_z, 0.0, 1.0); }
// 002's randomjitter: a hash of the pixel and the time in [-0.5, 0.5].
float random_jitter(vec2 pos) {
    return clamp(fract(sin(dot(vec4(pos, frame.time, frame.time * 0.3), vec4(12.9898, 78.233, 45.164, 94.673))) * 43758.5453) - 0.5,
                 -0.5, 0.5);
}

void main() {
    ivec2 X = ivec2(gl_FragCoord.xy), size = ivec2(frame.resolution.xy);
    vec2 vn = texelFetch(neighbourmax, X / params.tile, 0).xy;
    vec4 cX = texelFetch(color, X, 0);
    if (length(vn) < kEarlyOut) {
        result = cX;
        return;
    }
    vec4 tX = texelFetch(vq, X, 0);
    float lvX = length(tX.xy), zX = -tX.z;
    float weight = 1.0 / max(length(vn), 1e-8);
    vec4 sum = cX * weight;
    float j = params.jitter ? random_jitter(vec2(X)) : 0.0;
    int S = params.taps, Sm = (S - 1) / 2;
    for (int i = 0; i <= S; ++i) {
        if (i == Sm) continue;  // as printed: the centre is X itself, already in the sum
        float t = mix(-1.0, 1.0, (float(i) + j + 1.0) / float(S + 1));
        ivec2 Y = clamp(ivec2(vec2(X) + vn * t + 0.5), ivec2(0), size - 1);
        vec4 tY = texelFetch(vq, Y, 0);
        float lvY = length(tY.xy), lXY = length(vec2(X - Y)), zY = -tY.z;
        float f = soft_depth_compare(zX, zY), b = soft_depth_compare(zY, zX);
        float alphaY = f * cone(lXY, lvY) + b * cone(lXY, lvX) + cylinder(lXY, lvY) * cylinder(lXY, lvX) * 2.0;
        weight += alphaY;
        sum += texelFetch(color, Y, 0) * alphaY;
    }
    result = sum / max(weight, 1e-8);
}
