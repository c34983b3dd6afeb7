float one() { return 1.0; }
float two() { return 2.0; }
