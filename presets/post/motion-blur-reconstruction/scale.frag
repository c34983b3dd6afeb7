#version 450
// Velocity scaling of 002_644d46bdce7e5305.txt L1000-1002, listing L1041-1046 (McGuire et al. 2012):
//   q = 1/2 (X - X') * exposure * framerate
//   V[X] = q * max(0.5 px, min(|q|, k)) / (|q| + eps)
// The document's X - X' is in NDC (a pitfall: the blur then depends on the aspect ratio);
// passes/motion/velocity.glsl already converts it to pixels, 1/2 included, so q = v * shutter.
// Clamping to k (the tile size) bounds the blur by what NeighbourMax can see; the half-pixel
// floor keeps slow pixels from dividing by ~0 in the cone weights. View depth rides along in z.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 vq;
uniform sampler2D velocity;

const float kEps = 1e-4;

void main() {
    vec4 v = texelFetch(velocity, ivec2(gl_FragCoord.xy), 0);
    vec2 q = v.xy * params.shutter;
    float len = length(q);
    vec2 V = q * max(0.5, min(len, float(params.tile))) / (len + kEps);
    vq = vec4(V, v.z, 1.0);
}
