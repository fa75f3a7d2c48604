// Lighting helpers shared by the shaders.
float lambert(vec3 n, vec3 l) {
  return max(dot(normalize(n), normalize(l)), 0.0);
}
