#version 450
// Coloured points, lines and triangles: the 2D view's map and lattice, the 3D view's lattice.
#extension GL_GOOGLE_include_directive : require
#include "render_common.glsl"
layout(location = 0) in vec3 in_position;
layout(location = 1) in vec4 in_colour;
layout(location = 0) out vec4 out_colour;
void main() {
  out_colour = in_colour;
  gl_Position = frame.view_projection * vec4(in_position, 1.0);
}
