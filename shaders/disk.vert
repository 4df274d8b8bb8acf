#version 450
// An element in the 2D view: a disk of its diameter at its map position (one quad per instance).
#extension GL_GOOGLE_include_directive : require
#include "render_common.glsl"
layout(location = 0) in vec2 in_centre;
layout(location = 1) in float in_radius;
layout(location = 2) in vec4 in_colour;
layout(location = 0) out vec2 out_local;
layout(location = 1) out vec4 out_colour;
const vec2 corners[6] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, -1), vec2(1, 1), vec2(-1, 1));
void main() {
  vec2 local = corners[gl_VertexIndex];
  out_local = local;
  out_colour = in_colour;
  gl_Position = frame.view_projection * vec4(in_centre + in_radius * local, 0.5, 1.0);
}
