const SCALE = '2.0';

export const outline = /* glsl */ `#version 300 es
precision mediump float;
uniform vec4 u_outline;
out vec4 outColor;
void main() {
  outColor = u_outline * ${SCALE};
}
`;
