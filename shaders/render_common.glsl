// Shared by the renderer's shaders: the push-constant block every pipeline uses.
layout(push_constant) uniform Frame {
  mat4 view_projection;
  vec4 eye;          // xyz: camera position (3D); unused in 2D
  vec4 light;        // xyz: direction towards the light
} frame;

// Soft two-sided lighting: ambient, a key light and a little fill from the camera.
vec3 shade(vec3 base, vec3 n, vec3 position) {
  vec3 l = normalize(frame.light.xyz);
  vec3 v = normalize(frame.eye.xyz - position);
  if (dot(n, v) < 0.0) n = -n;
  float diffuse = max(dot(n, l), 0.0);
  float fill = max(dot(n, v), 0.0);
  vec3 h = normalize(l + v);
  float specular = pow(max(dot(n, h), 0.0), 48.0);
  return base * (0.28 + 0.55 * diffuse + 0.22 * fill) + vec3(0.25) * specular;
}
