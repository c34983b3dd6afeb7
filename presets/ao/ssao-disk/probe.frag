#version 450
// Test read-out: the visibility at the receiver, the centre pixel of the view (scene probe).
layout(location = 0) out float probe;
uniform sampler2D ao;
void main() { probe = texelFetch(ao, textureSize(ao, 0) / 2, 0).r; }
