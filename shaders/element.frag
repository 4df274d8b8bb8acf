#version 450
#extension GL_GOOGLE_include_directive : require
#include "render_common.glsl"
layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_colour;
layout(location = 0) out vec4 out_colour;
void main() {
  // Faceted shapes (gems, prisms) read best with flat normals; derivatives give them for free.
  vec3 n = normalize(cross(dFdx(in_position), dFdy(in_position)));
  out_colour = vec4(shade(in_colour, n, in_position), 1.0);
}
