#version 450
// An element: its shape's vertex (unit diameter, +Z up) scaled to the diameter, turned so +Z
// follows the surface normal, moved to the centre. The same transform the PLY/OBJ export uses.
#extension GL_GOOGLE_include_directive : require
#include "render_common.glsl"
layout(location = 0) in vec3 in_vertex;
layout(location = 1) in vec3 in_centre;
layout(location = 2) in vec3 in_normal;
layout(location = 3) in float in_diameter;
layout(location = 4) in vec4 in_colour;
layout(location = 0) out vec3 out_position;
layout(location = 1) out vec3 out_colour;

mat3 frame_for(vec3 n) {
  // Any unit vector not parallel to n gives a tangent; the choice only spins the element.
  vec3 helper = abs(n.z) < 0.9 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0);
  vec3 t = normalize(cross(helper, n));
  vec3 b = cross(n, t);
  return mat3(t, b, n);
}

void main() {
  vec3 world = in_centre + frame_for(normalize(in_normal)) * (in_vertex * in_diameter);
  out_position = world;
  out_colour = in_colour.rgb;
  gl_Position = frame.view_projection * vec4(world, 1.0);
}
