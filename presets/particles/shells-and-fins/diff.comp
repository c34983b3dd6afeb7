#version 450
// emitted - brute in one word, so a test can require the two counts to agree exactly.
layout(local_size_x = 1) in;
layout(std430) buffer Fins { uint emitted; uint brute; int diff; } fins;
void main() { fins.diff = int(fins.emitted) - int(fins.brute); }
