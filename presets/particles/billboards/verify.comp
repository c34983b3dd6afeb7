#version 450
// Test-only, one thread per sprite, with the same corner function the vertex shader uses:
//   r.x = 1 - |n . f|   n = the quad's normal, f = the view axis (screen mode) or the horizontal
//                       direction to the eye (axis mode): 0 when the quad faces as it should
//   r.y = covered pixels / (pi rho^2) - 1, rho = size * proj[1][1] * h/2 / z_view: a quad
//         parallel to the image plane projects to a disc of radius rho px, so its size falls off
//         exactly as 1 / view depth (screen mode only; the rasterised count has ~0.5% edge noise)
//   r.z = |x(top) - x(bottom)| in pixels of the quad's centre line (vertical on screen)
//   r.w = 1 - up . axis  (axis mode: the quad keeps the world axis as its up direction)
layout(local_size_x = 64) in;
#include "sprites.glsl"
layout(std430) readonly buffer Coverage { uint pixels[]; } coverage;
layout(std430) writeonly buffer Residual { vec4 r[]; } residual;
vec2 to_px(vec3 p) {
    vec4 c = frame.view_proj * vec4(p, 1.0);
    return (c.xy / c.w * 0.5 + 0.5) * frame.resolution.xy;
}
void main() {
    int i = int(gl_GlobalInvocationID.x);
    if (i >= SPRITES) return;
    vec3 c = sprite_centre(i);
    vec3 o = sprite_corner(i, vec2(0.0));
    vec3 e1 = sprite_corner(i, vec2(1, 0)) - o, e2 = sprite_corner(i, vec2(0, 1)) - o;
    vec3 n = normalize(cross(e1, e2));
    vec3 to_eye = frame.camera_pos.xyz - c;
    vec3 f = params.mode == MODE_AXIS ? normalize(vec3(to_eye.x, 0.0, to_eye.z)) : frame.inv_view[2].xyz;
    float z_view = -(frame.view * vec4(c, 1.0)).z;
    float rho = params.size * frame.proj[1][1] * 0.5 * frame.resolution.y / z_view;
    float area = 3.14159265 * rho * rho;
    float dx = abs(to_px(sprite_corner(i, vec2(0, 1))).x - to_px(sprite_corner(i, vec2(0, -1))).x);
    residual.r[i] = vec4(1.0 - abs(dot(n, f)), float(coverage.pixels[i]) / area - 1.0, dx,
                         1.0 - dot(normalize(e2), vec3(0, 1, 0)));
}
