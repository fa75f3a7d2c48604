#version 300 es
// Copy of gouraud-phong.frag (article 002), which compiles as published: no fix needed.
// It exists so that gouraud-phong.fixed.vert has a fragment shader of the same name to link with.

// Fragment shaders don't have a default precision so we need
// to pick one. mediump is a good default. It means "medium precision"
precision mediump float;

// Computed color coming from the vertex shader
in vec4 vVertexColor;

// We need to declare an output for the fragment shader
out vec4 fragColor;

void main() {
  fragColor = vVertexColor;
}
