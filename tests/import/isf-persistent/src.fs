/*{
  "DESCRIPTION": "A 1x1 persistent float buffer counts frames; the output shows it.",
  "CREDIT": "passlab tests",
  "ISFVSN": "2",
  "CATEGORIES": ["test"],
  "INPUTS": [],
  "PASSES": [
    { "TARGET": "state", "PERSISTENT": true, "FLOAT": true, "WIDTH": "1", "HEIGHT": "1" },
    {}
  ]
}*/
void main() {
    if (PASSINDEX == 0) {
        // State: r counts frames (float: beyond 8 bits), g holds FRAMEINDEX, b the summed TIMEDELTA.
        vec4 last = IMG_PIXEL(state, vec2(0.5));
        gl_FragColor = vec4(last.r + 1.0, float(FRAMEINDEX), last.b + TIMEDELTA, 1.0);
    } else {
        vec4 s = IMG_NORM_PIXEL(state, vec2(0.5));
        gl_FragColor = vec4(s.r / 400.0, isf_FragNormCoord, 1.0);
    }
}
