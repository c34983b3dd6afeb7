/*{
  "DESCRIPTION": "a trailing comma is not JSON",
  "INPUTS": [
    { "NAME": "gain", "TYPE": "float", "DEFAULT": 0.5, },
  ]
}*/
void main() { gl_FragColor = vec4(gain); }
