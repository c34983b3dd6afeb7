// The shared OIT scene (docs/catalogue.md 3.10): transparent quads that one draw instances, each an
// NDC rectangle (Vulkan: y = -1 is the top row) on a depth plane, so every OIT preset and every
// analytic reference evaluates the same geometry. Depth is NDC z in [0, 1] (smaller is nearer).
//   0-2  three flat overlapping quads (sorting per object gets these right);
//   3-4  two quads whose depth planes cross (an intersection: each is in front on one side);
//   5-8  a pinwheel of tilted bars, each in front of the previous one where they overlap, so
//        A < B < C < D < A: a cyclic overlap no per-object order can draw
//        (000_c9f7e5de708ecbb3.txt L4156-4157 name both failures of sorting).
// With params.stack = k > 0 the first k instances become full-screen quads at distinct depths
// and the rest vanish: k * W * H fragments, the counted case (depth complexity k, up to 32).
// The draw always has OIT_INSTANCES instances; those past the scene's 9 (or past k) have zero area.
const int OIT_QUADS = 9;
const int OIT_INSTANCES = 32;

struct OitQuad { vec4 rect; vec3 plane; vec3 rgb; };   // rect (x0,y0,x1,y1); z = p.x + p.y*(x-cx) + p.z*(y-cy)

const OitQuad kOitQuads[OIT_QUADS] = OitQuad[](
    OitQuad(vec4(-0.90, -0.90, -0.30, -0.20), vec3(0.50, 0.0, 0.0), vec3(1.0, 0.15, 0.1)),
    OitQuad(vec4(-0.60, -0.60,  0.00,  0.10), vec3(0.35, 0.0, 0.0), vec3(0.1, 0.9, 0.2)),
    OitQuad(vec4(-0.75, -0.45, -0.15, -0.05), vec3(0.65, 0.0, 0.0), vec3(0.15, 0.3, 1.0)),
    OitQuad(vec4(-0.90,  0.20, -0.10,  0.90), vec3(0.50,  0.5, 0.0), vec3(1.0, 0.9, 0.1)),
    OitQuad(vec4(-0.80,  0.30,  0.00,  0.80), vec3(0.50, -0.5, 0.0), vec3(0.1, 0.85, 0.95)),
    OitQuad(vec4( 0.10, -0.60,  0.80, -0.40), vec3(0.50,  0.4 / 0.7, 0.0), vec3(1.0, 0.55, 0.05)),
    OitQuad(vec4( 0.60, -0.60,  0.80,  0.20), vec3(0.50, 0.0,  0.5), vec3(0.6, 0.2, 0.9)),
    OitQuad(vec4( 0.10,  0.00,  0.80,  0.20), vec3(0.50, -0.4 / 0.7, 0.0), vec3(0.1, 0.7, 0.6)),
    OitQuad(vec4( 0.10, -0.60,  0.30,  0.20), vec3(0.50, 0.0, -0.5), vec3(1.0, 0.4, 0.7)));

// The opaque occluder: a grey bar at depth 0.45 across the view (behind quad 1, in front of 0
// and 2), over the background colour. The transparent quads are depth-tested against it.
const vec4  kOitOpaqueRect  = vec4(-1.0, -0.15, 1.0, -0.05);
const float kOitOpaqueDepth = 0.45;
const vec3  kOitOpaqueRgb   = vec3(0.5);
const vec3  kOitBackground  = vec3(0.08, 0.08, 0.1);

// Quad q of the scene, or of the full-screen stack of `stack` quads (an empty rect off screen: zero area).
OitQuad oit_quad(int q, int stack) {
    if (stack <= 0) return q < OIT_QUADS ? kOitQuads[q] : OitQuad(vec4(2.0), vec3(0.0), vec3(0.0));
    if (q >= stack) return OitQuad(vec4(2.0), vec3(0.0), vec3(0.0));
    return OitQuad(vec4(-1.0, -1.0, 1.0, 1.0), vec3(float(q + 1) / float(stack + 2), 0.0, 0.0),
                   kOitQuads[q % OIT_QUADS].rgb);
}

float oit_depth(OitQuad k, vec2 ndc) {
    vec2 c = 0.5 * (k.rect.xy + k.rect.zw);
    return k.plane.x + k.plane.y * (ndc.x - c.x) + k.plane.z * (ndc.y - c.y);
}
