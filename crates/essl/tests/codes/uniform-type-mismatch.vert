#version 300 es
uniform vec3 u_light;
void main() { gl_Position = vec4(u_light, 1.0); }
