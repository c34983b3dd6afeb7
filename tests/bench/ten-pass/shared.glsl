// Included by every pass: editing it rebuilds all ten.
vec3 shade(vec3 c, float stage) { return c * /*KNOB*/1.0 + 0.01 * stage; }
