#version 450
// Keeps the fragments with uv[AXIS] < 0.5 (AXIS 0: the left half, 1: the top half; uv (0, 0) is
// the top-left texel) and discards the rest, so only those get the stencil reference.
layout(location = 0) in vec2 uv;
void main() { if (uv[AXIS] > 0.5) discard; }
