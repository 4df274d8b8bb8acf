#version 450
layout(location = 0) in vec2 in_local;
layout(location = 1) in vec4 in_colour;
layout(location = 0) out vec4 out_colour;
void main() {
  float r = length(in_local);
  if (r > 1.0) discard;
  // A dark rim so touching disks stay distinguishable.
  out_colour = r > 0.86 ? vec4(in_colour.rgb * 0.35, 1.0) : vec4(in_colour.rgb, 1.0);
}
