#version 450
#extension GL_GOOGLE_include_directive : require
#include "render_common.glsl"
layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 0) out vec4 out_colour;
void main() {
  out_colour = vec4(shade(vec3(0.62, 0.63, 0.66), normalize(in_normal), in_position), 1.0);
}
