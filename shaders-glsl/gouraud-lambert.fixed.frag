#version 300 es
// Copy of gouraud-lambert.frag (article 002), which compiles as published: no fix needed.
// It exists so that gouraud-lambert.fixed.vert has a fragment shader of the same name to link with.
precision mediump float;
// Expect the interpolated value fro, the vertex shader
in vec4 vVertexColor;
// Return the final color as fragColor
out vec4 fragColor;
void main(void) {
  // Simply set the value passed in from the vertex shader
  fragColor = vVertexColor;
}
