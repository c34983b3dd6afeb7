// Nine teapots in a row receding from the camera, 2.6 units apart, alternating left and right (this preset's scene).
#define TEAPOTS 9
#define TEAPOT_RADIUS 0.8
vec3 teapot_centre(int i) { return vec3(float(i % 2) * 2.2 - 1.1, 0.0, -2.6 * float(i)); }
