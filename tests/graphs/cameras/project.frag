#version 450
// Known world points through every camera's matrices, read by name from the cameras block.
layout(location = 0) out vec4 color;
void main() {
    const vec4 P = vec4(1.0, 2.0, 3.0, 1.0);
    int x = int(gl_FragCoord.x);
    vec4 r = vec4(0.0);
    if (x == 0) r = cameras.sun.view_proj * P;
    else if (x == 1) r = cameras.spot.view_proj * P;
    else if (x == 2) r = cameras.distant.view_proj * P;
    else if (x == 3) r = cameras.distant.view_proj * vec4(0.0, 0.0, -1.0, 0.0);  // a point at infinity
    else if (x == 4) r = frame.proj * vec4(0.0, 0.0, -1.0, 0.0);                  // [view] far = inf
    else if (x == 5) r = cameras.sun.inv_view_proj * (cameras.sun.view_proj * P);
    else if (x == 6) r = cameras.sun.position;
    else if (x == 7) r = cameras.sun.clip;
    color = r;
}
