#version 450
// EXERCISE — edge detection in image space: fill in the three TODO blocks. As shipped every
// response is 0 (no ink anywhere).
//     passlab run   npr/edge-detection --exercise presets/npr/edge-detection/exercise
//     passlab grade npr/edge-detection --exercise presets/npr/edge-detection/exercise
// Pixel rows: p.y grows from row 0 (t = the row above, p.y - 1) to the last (b = p.y + 1).
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
    // TODO 1: profile edges, a 1st order differential (000 L3190-3191): the Sobel operator on
    // the 3 x 3 neighbourhood above, Gx = [-1 0 1; -2 0 2; -1 0 1] * D (right column minus left),
    // Gy = its transpose (row below minus row above), and the gradient's magnitude
    // |G| = sqrt(Gx^2 + Gy^2), which does not depend on the edge's direction.
    float sobel = 0.0;
    // TODO 2: internal edges, a 2nd order differential (000 L3192-3193): the 4-neighbour Laplace
    //     L = D(x+1) + D(x-1) + D(y+1) + D(y-1) - 4 D(x)
    // Sum the four differences (neighbour - c) rather than the values: that keeps a linear
    // ramp's L at rounding level.
    float laplace = 0.0;
    // TODO 3: creases from the normal buffer (000 L3207-3210, "depth buffer AND normal buffer"):
    // 1 - the smallest n . n' over the 4 neighbours n' of n = N(p) (the most different one).
    float crease = 0.0;
    edges = vec4(sobel, laplace, crease, 0.0);
}
