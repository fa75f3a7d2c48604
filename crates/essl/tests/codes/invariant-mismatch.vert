attribute vec4 a_position;
invariant varying vec4 v_color;
void main() {
    v_color = a_position;
    gl_Position = a_position;
}
