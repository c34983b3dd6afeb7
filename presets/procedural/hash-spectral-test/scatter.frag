#version 450
layout(location = 0) out float hits;
void main() { hits = 1.0; }
