#version 300 es
// An unsigned-integer colour output at location 0.
precision highp float;
layout(location = 0) out uvec4 o_value;
void main() {
  o_value = uvec4(7u, 8u, 9u, 10u);
}
