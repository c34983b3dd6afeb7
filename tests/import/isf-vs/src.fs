/*{
  "DESCRIPTION": "A .vs companion passes a varying: the colour of the left neighbour's coordinate.",
  "INPUTS": [ { "NAME": "shift", "TYPE": "float", "DEFAULT": 0.25 } ]
}*/
varying vec2 shifted;
void main() {
    gl_FragColor = vec4(shifted, isf_FragNormCoord.x, 1.0);
}
