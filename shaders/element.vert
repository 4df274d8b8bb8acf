#version 450
// An element: its shape's vertex (unit diameter, +Z up) placed by the frame the engine computed
// (elements/element_frame.h, the exporters' rule): centre + diameter * (v.x t + v.y b + v.z n).
#extension GL_GOOGLE_include_directive : require
#include "render_common.glsl"
layout(location = 0) in vec3 in_vertex;
layout(location = 1) in vec3 in_centre;
layout(location = 2) in vec3 in_normal;
layout(location = 3) in float in_diameter;
layout(location = 4) in vec4 in_colour;
layout(location = 5) in vec3 in_tangent;
layout(location = 6) in vec3 in_bitangent;
layout(location = 0) out vec3 out_position;
layout(location = 1) out vec3 out_colour;

void main() {
  vec3 local = in_vertex * in_diameter;
  vec3 world = in_centre + local.x * in_tangent + local.y * in_bitangent + local.z * in_normal;
  out_position = world;
  out_colour = in_colour.rgb;
  gl_Position = frame.view_projection * vec4(world, 1.0);
}
