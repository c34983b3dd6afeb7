#version 450
// A scene spread in depth, ray-traced analytically per pixel (camera at the origin looking down
// -z, 45 degree vertical field of view): three balls at 2.5, 4 and 6 units and a wall at 8 with
// a checker (detail to blur). Writes the colour and the Vulkan depth-buffer value
//   d = zf (z - zn) / (z (zf - zn))     (zn = 0.1, zf = 100)
// so the CoC pass works from a depth buffer, as 002's does.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
layout(location = 1) out float depth;
const float kNear = 0.1, kFar = 100.0;
void main() {
    float t = tan(radians(22.5));
    vec3 dir = normalize(vec3((uv.x * 2.0 - 1.0) * t * frame.aspect, (1.0 - uv.y * 2.0) * t, -1.0));
    float best = 8.0 / -dir.z;  // the wall z = -8
    vec3 hit = dir * best;
    vec2 cell = floor(hit.xy * 2.0);
    vec3 c = mod(cell.x + cell.y, 2.0) < 1.0 ? vec3(0.85, 0.8, 0.7) : vec3(0.25, 0.3, 0.4);
    const vec4 balls[3] = vec4[](vec4(-0.8, -0.2, -2.5, 0.35), vec4(0.3, 0.0, -4.0, 0.6), vec4(1.6, 0.4, -6.0, 0.8));
    const vec3 tints[3] = vec3[](vec3(0.95, 0.35, 0.2), vec3(0.3, 0.85, 0.4), vec3(0.3, 0.5, 0.95));
    for (int i = 0; i < 3; ++i) {
        vec3 o = -balls[i].xyz;  // ray from the origin: solve |t dir - centre| = r
        float b = dot(dir, o), q = dot(o, o) - balls[i].w * balls[i].w, disc = b * b - q;
        if (disc > 0.0) {
            float s = -b - sqrt(disc);
            if (s > 0.0 && s < best) {
                best = s;
                vec3 n = normalize(dir * s - balls[i].xyz);
                c = tints[i] * (0.25 + 0.75 * max(dot(n, normalize(vec3(0.4, 0.6, 0.7))), 0.0));
            }
        }
    }
    float z = -(dir * best).z;
    color = vec4(c, 1.0);
    depth = kFar * (z - kNear) / (z * (kFar - kNear));
}
