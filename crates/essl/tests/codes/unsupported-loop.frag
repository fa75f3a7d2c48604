precision mediump float;
uniform int u_steps;
void main() {
    float sum = 0.0;
    for (int i = 0; i < u_steps; i++) {
        sum += 0.1;
    }
    int k = 0;
    while (k < 4) {
        k++;
    }
    gl_FragColor = vec4(sum, float(k), 0.0, 1.0);
}
