varying vec2 shifted;
void main() {
    isf_vertShaderInit();
    // INPUTS are visible in the vertex stage too.
    shifted = isf_FragNormCoord * 0.5 + vec2(shift, 0.0);
}
