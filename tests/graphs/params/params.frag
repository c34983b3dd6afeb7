#version 450
// Column x shows param x; the params block and the MODE_* defines come from [params].
layout(location = 0) out vec4 color;
void main() {
    int x = int(gl_FragCoord.x);
    if (x == 0) color = vec4(params.f, 0, 0, 1);
    else if (x == 1) color = vec4(float(params.i), 0, 0, 1);
    else if (x == 2) color = vec4(params.b ? 1.0 : 0.0, 0, 0, 1);
    else if (x == 3) color = vec4(params.v2, 0, 1);
    else if (x == 4) color = vec4(params.v3, 1);
    else if (x == 5) color = params.v4;
    else if (x == 6) color = vec4(params.col, 1);
    else color = vec4(float(params.mode), params.mode == MODE_MIDDLE ? 1.0 : 0.0, 0, 1);
}
