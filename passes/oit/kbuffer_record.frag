#version 450
// k-buffer pass one: record the k nearest depths per pixel (oit/kbuffer.glsl). Depth-only pass;
// early fragment tests, so fragments behind the opaque scene never enter the list.
#include "oit/kbuffer.glsl"
layout(early_fragment_tests) in;
void main() { oit_kbuffer_insert(); }
