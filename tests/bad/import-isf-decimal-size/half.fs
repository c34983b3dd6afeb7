/*{
  "PASSES": [ { "TARGET": "small", "WIDTH": "$WIDTH*0.5", "HEIGHT": "$HEIGHT*0.5" }, {} ]
}*/
void main() { gl_FragColor = PASSINDEX == 0 ? vec4(1.0) : IMG_THIS_NORM_PIXEL(small); }
