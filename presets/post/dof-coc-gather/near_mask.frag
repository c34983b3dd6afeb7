#version 450
// Tests: 1 on the nearest ball (view depth z < 3; it spans 2.15..2.85, everything else is at 3.4
// or beyond), 0 elsewhere: the mask of gather's "in-focus foreground stays sharp" case.
// z from the depth-buffer value d = zf (z - zn) / (z (zf - zn)) of scene.frag.
layout(location = 0) out float near;
uniform sampler2D depth;
const float kNear = 0.1, kFar = 100.0;
void main() {
    float d = texelFetch(depth, ivec2(gl_FragCoord.xy), 0).r;
    float z = kFar * kNear / (kFar - d * (kFar - kNear));
    near = z < 3.0 ? 1.0 : 0.0;
}
