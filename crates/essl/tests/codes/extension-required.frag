// essl-target: webgl1 (a context that enabled OES_standard_derivatives)
precision mediump float;
varying vec2 v_uv;
void main() {
    gl_FragColor = vec4(fwidth(v_uv), 0.0, 1.0);
}
