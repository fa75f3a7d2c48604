precision mediump float;
uniform int u_count;
out vec4 color;
void main() {
    int odd = u_count % 2;
    color = vec4(float(odd));
}
