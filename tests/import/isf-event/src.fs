/*{
  "DESCRIPTION": "An event input counted in a persistent buffer: true for one frame only.",
  "INPUTS": [ { "NAME": "fire", "TYPE": "event" }, { "NAME": "gain", "TYPE": "float", "DEFAULT": 0.5, "MIN": 0.0, "MAX": 1.0 },
              { "NAME": "on", "TYPE": "bool", "DEFAULT": true }, { "NAME": "tint", "TYPE": "color", "DEFAULT": [0.25, 0.5, 0.75, 1.0] },
              { "NAME": "where", "TYPE": "point2D", "DEFAULT": [3.0, 4.0] } ],
  "PASSES": [ { "TARGET": "count", "PERSISTENT": true, "FLOAT": true, "WIDTH": "1", "HEIGHT": "1" }, {} ]
}*/
void main() {
    if (PASSINDEX == 0) {
        vec4 c = IMG_PIXEL(count, vec2(0.5));
        gl_FragColor = vec4(c.r + (fire ? 1.0 : 0.0), gain, on ? 1.0 : 0.0, where.x + where.y);
    } else {
        gl_FragColor = tint;
    }
}
