// Buffer C

void mainImage(out vec4 c, in vec2 p) {
    c = undefined_thing;
}
