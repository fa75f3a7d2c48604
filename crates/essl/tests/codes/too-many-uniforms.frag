// essl-target: webgl1
precision mediump float;
// 20 vectors: more than the 16 a WebGL 1 fragment shader is guaranteed.
uniform vec4 u_palette[20];
void main() {
    vec4 sum = vec4(0.0);
    for (int i = 0; i < 20; i++) {
        sum += u_palette[i];
    }
    gl_FragColor = sum;
}
