#version 300 es
precision highp float;
flat in uint v_id;
out vec4 o_color;
void main() {
  o_color = vec4(float(v_id) / 255.0, 0.0, 0.0, 1.0);
}
