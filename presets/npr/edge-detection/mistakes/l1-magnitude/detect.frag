#version 450
// Edge operators on the G-buffer (000_c9f7e5de708ecbb3.txt L3187-3210):
//   profile edges, 1st order:  Sobel  Gx = [-1 0 1; -2 0 2; -1 0 1] * D,  Gy = its transpose,
//                              |G| = sqrt(Gx^2 + Gy^2)
//   internal edges, 2nd order: Laplace L = D(x+1) + D(x-1) + D(y+1) + D(y-1) - 4 D(x)
//   creases (G-buffer only):   1 - min over the 4 neighbours of n . n'
// D is the depth-buffer value, here 1 / view depth: like the hardware z-buffer it is affine in
// screen position on a plane, so L = 0 on every plane and only creases and silhouettes respond
// (linear view depth would light up every tilted plane under perspective).
// Output: (|G|, L, crease, 0). Out-of-image neighbours repeat the border (clamp).
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 edges;
uniform sampler2D inv_depth;
uniform sampler2D normal;

float D(ivec2 p) { return texelFetch(inv_depth, clamp(p, ivec2(0), ivec2(frame.resolution.xy) - 1), 0).r; }
vec3 N(ivec2 p) { return texelFetch(normal, clamp(p, ivec2(0), ivec2(frame.resolution.xy) - 1), 0).xyz; }

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    float tl = D(p + ivec2(-1, -1)), t = D(p + ivec2(0, -1)), tr = D(p + ivec2(1, -1));
    float l = D(p + ivec2(-1, 0)), c = D(p), r = D(p + ivec2(1, 0));
    float bl = D(p + ivec2(-1, 1)), b = D(p + ivec2(0, 1)), br = D(p + ivec2(1, 1));
    float gx = (tr + 2.0 * r + br) - (tl + 2.0 * l + bl);
    float gy = (bl + 2.0 * b + br) - (tl + 2.0 * t + tr);
    // Differences first, then the sum: keeps a linear ramp's Laplace at rounding level.
    float laplace = (r - c) + (l - c) + (t - c) + (b - c);
    vec3 n = N(p);
    float min_dot = min(min(dot(n, N(p + ivec2(1, 0))), dot(n, N(p + ivec2(-1, 0)))),
                        min(dot(n, N(p + ivec2(0, 1))), dot(n, N(p + ivec2(0, -1)))));
    edges = vec4(abs(gx) + abs(gy), laplace, 1.0 - min_dot, 0.0);
}
