/*{
  "DESCRIPTION": "WIDTH/HEIGHT expressions: a half-size pass and one whose width follows an input.",
  "INPUTS": [ { "NAME": "cells", "TYPE": "long", "VALUES": [2, 4, 8], "LABELS": ["Two", "Four", "Eight"], "DEFAULT": 4 } ],
  "PASSES": [
    { "TARGET": "halfsize", "WIDTH": "floor($WIDTH/2)", "HEIGHT": "$HEIGHT/2" },
    { "TARGET": "strip", "WIDTH": "max($cells, 1)", "HEIGHT": "1" },
    {}
  ]
}*/
void main() {
    if (PASSINDEX == 0) {
        gl_FragColor = vec4(RENDERSIZE / 100.0, 0.0, 1.0);
    } else if (PASSINDEX == 1) {
        gl_FragColor = vec4(RENDERSIZE / 100.0, float(cells) / 100.0, 1.0);
    } else {
        gl_FragColor = vec4(IMG_SIZE(halfsize) / 100.0, IMG_SIZE(strip).x / 100.0, 1.0);
    }
}
