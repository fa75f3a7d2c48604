#version 300 es
// Chromium: compiles. essl: rejects (not-assignable: "this expression cannot be assigned (it is not a variable)"; glslang rejects too): ANGLE takes a comma expression ending in a variable as an l-value.
void main() {
    float v = 0.0;
    (v, v) = 1.0;
    gl_Position = vec4(v);
}
