#pragma once
// The studio's window and the Vulkan device the app owns: GLFW, a context with a graphics queue
// that can present (lent to the renderer and to ImGui), the window surface with a swapchain of
// our own, the render pass ImGui draws in, and the frame loop. The swapchain images can be copied
// out (TRANSFER_SRC), so a screenshot is exactly what was presented.
#include "synthetic_input.h"
#include "renderer.h"

#include "paver/compute/vulkan_context.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

struct GLFWwindow;

namespace paver::studio {

class ViewImages;

struct WindowOptions {
  int width = 1280, height = 800;  // logical size of the window
  bool vsync = true;               // false: present as fast as possible (scripts)
};

class AppWindow {
public:
  explicit AppWindow(const WindowOptions& options);  // throws std::runtime_error saying what failed
  ~AppWindow();
  AppWindow(const AppWindow&) = delete;
  AppWindow& operator=(const AppWindow&) = delete;

  const std::shared_ptr<gpu::VulkanContext>& context() const { return context_; }
  GLFWwindow* glfw() const { return window_; }
  ViewImages& view_images() { return *images_; }

  bool close_requested() const;  // the close button was pressed (or request_close)
  void cancel_close();
  void request_close();
  std::vector<std::string> take_dropped_paths();  // files dropped on the window since last asked
  bool can_capture() const;  // the swapchain images can be copied out (screenshots)

  // Polls events and starts an ImGui frame; false while the window is minimised (draw nothing).
  // With `input`, the frame sees that mouse and key state instead of the real one (a script's).
  bool begin_frame(const InputFrame* input = nullptr);
  // Renders ImGui's frame and presents it. With `capture`, returns the presented image as RGBA.
  std::optional<render::Image> end_frame(bool capture);

  struct Swapchain;

private:
  void open(const WindowOptions& options);
  void shut_down();
  void rebuild_swapchain();

  GLFWwindow* window_ = nullptr;
  std::shared_ptr<gpu::VulkanContext> context_;
  std::unique_ptr<Swapchain> swapchain_;
  std::unique_ptr<ViewImages> images_;
  std::vector<std::string> dropped_;
  bool imgui_ready_ = false;
  int injected_key_ = -1;  // the key a script held down last frame, released this one
  bool injected_ = false;  // last frame's input was a script's
};

}  // namespace paver::studio
