precision mediump float;
void main() {
    float sum = 0.0;
    for (int i = 0; i < 8; i++) {
        sum += 0.1;
        if (sum > 0.5) i = 8;
    }
    gl_FragColor = vec4(sum);
}
