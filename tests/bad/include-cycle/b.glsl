float b();
#include "a.glsl"
