#version 450
// Paver Studio: samples a renderer view (opaque: the views have no transparency to show).
layout(set = 0, binding = 0) uniform sampler2D view_image;
layout(location = 0) in vec2 in_uv;
layout(location = 1) in vec4 in_colour;
layout(location = 0) out vec4 out_colour;
void main() {
  out_colour = vec4(in_colour.rgb * texture(view_image, in_uv).rgb, 1.0);
}
