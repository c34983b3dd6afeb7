#version 450
#line 99999999999 "a:99999999999: "
void main() { undefined_name = 1; }
