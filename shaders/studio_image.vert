#version 450
// Paver Studio: a renderer view drawn inside ImGui. The same vertex layout and push constants as
// ImGui's Vulkan backend (ImDrawVert; scale and translate to clip space), so the backend's own
// vertex and index buffers draw it.
layout(location = 0) in vec2 in_position;
layout(location = 1) in vec2 in_uv;
layout(location = 2) in vec4 in_colour;
layout(push_constant) uniform Push {
  vec2 scale;
  vec2 translate;
} push;
layout(location = 0) out vec2 out_uv;
layout(location = 1) out vec4 out_colour;
void main() {
  out_uv = in_uv;
  out_colour = in_colour;
  gl_Position = vec4(in_position * push.scale + push.translate, 0.0, 1.0);
}
