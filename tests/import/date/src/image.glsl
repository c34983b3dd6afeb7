void mainImage(out vec4 fragColor, in vec2 fragCoord) { fragColor = vec4(fract(iDate.w / 60.0)); }
