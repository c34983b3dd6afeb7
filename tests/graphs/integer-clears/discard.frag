#version 450
// Writes nothing: the target keeps the pass's attachment clear, which is what is tested.
layout(location = 0) out uvec4 color;
void main() { discard; }
