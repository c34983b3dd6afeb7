// helpers
float twice(float x) {
    return x * 2.0 + missing_value;
}
