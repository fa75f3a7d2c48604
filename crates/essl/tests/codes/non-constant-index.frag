precision mediump float;
uniform vec4 u_colors[8];
uniform int u_index;
void main() {
    gl_FragColor = u_colors[u_index];
}
