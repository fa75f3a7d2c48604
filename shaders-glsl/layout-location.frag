#version 300 es
// Added, not from the article: article 002 gives only the vertex shader of this
// layout(location) example. A minimal fragment shader that reads its varying.
precision mediump float;

in vec3 vVertexColor;

out vec4 fragColor;

void main() {
  fragColor = vec4(vVertexColor, 1.0);
}
