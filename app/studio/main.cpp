// paver-studio: the interactive editor of Paver. One window: the panels on the left, the 3D and
// 2D views on the right; the pavement re-runs in the background on every design change.
#include "app_window.h"
#include "command_line.h"
#include "recent_files.h"
#include "script_runner.h"
#include "studio.h"

#include "core/input_error.h"
#include "core/printable.h"

#include <CLI/CLI.hpp>

#include <csignal>
#include <cstdio>
#include <exception>
#include <optional>
#include <string>

int main(int argc, char** argv) {
  using namespace paver::studio;
  CLI::App app{"Paver Studio: design element patterns on a surface and watch them optimize", "paver-studio"};
  std::string surface, design, script, backend = "auto";
  WindowOptions window_options;
  app.add_option("SURFACE", surface, "Open surface to pave: OBJ, OFF, PLY or STL");
  app.add_option("--design", design, "design.json to start from");
  app.add_option("--script", script,
                 "Run the commands in FILE, one per frame, then quit (see app/studio/script.h); "
                 "a failing command exits non-zero");
  paver::app::add_backend_option(app, backend);
  app.add_option("--width", window_options.width, "Window width")->check(CLI::Range(320, 16384))->capture_default_str();
  app.add_option("--height", window_options.height, "Window height")->check(CLI::Range(240, 16384))->capture_default_str();
  if (const auto exit_code = paver::app::parse_command_line(app, argc, argv, "paver-studio [SURFACE] [--design F] [--script F]")) return *exit_code;
  // Past a file size limit an export fails and says so, as `paver run` does, instead of the
  // signal ending the studio with the user's unsaved design.
  std::signal(SIGXFSZ, SIG_IGN);

  try {
    // The script is read first: a typo fails before a window opens.
    std::optional<ScriptRunner> runner;
    if (!script.empty()) runner.emplace(load_script(script), script);
    window_options.vsync = !runner;
    AppWindow window(window_options);
    auto renderer = paver::render::Renderer::create(window.context());
    if (!renderer) throw std::runtime_error("the renderer: " + renderer.error().message);

    Studio s(window, *renderer.value());
    s.script_mode = runner.has_value();
    s.recent = load_recent_files(recent_files_path());
    set_backend(s, backend);
    if (!surface.empty()) open_surface(s, surface);
    if (!design.empty()) {
      open_any(s, design);
      // The design the studio starts with is where undo stops, not the built-in default.
      s.doc.history.clear();
    }

    while (!s.quit) {
      handle_close_request(s);
      // A script's mouse or key, one frame of it, taken only by a frame that is drawn.
      const InputFrame* input = s.input_queue.empty() ? nullptr : &s.input_queue.front();
      if (s.quit || !window.begin_frame(input)) continue;
      if (input) s.input_queue.pop_front();
      try {
        update_studio(s);
        if (runner) runner->frame(s);
      } catch (const std::exception& e) {
        report_error(s.doc, e);  // shown; the design and the session go on
      }
      draw_studio(s);
      after_present(s, window.end_frame(s.ui.screenshot.has_value()));
    }
    s.live.reset();  // a run still going is abandoned, not waited for
    if (runner)  // how the views were drawn (views_panel.cpp), for the session's tests
      for (int view : {0, 1}) {
        const ViewPace& pace = s.scene.pace[std::size_t(view)];
        const std::vector<double>& shown = s.scene.rendered[std::size_t(view)];
        std::printf("view %s: last full image %.1f ms, %d quick images, %d drawn in slices, showing %s\n",
                    view == 0 ? "3D" : "2D", pace.full_image_ms, pace.quick_images, pace.images_in_slices,
                    !shown.empty() && shown.back() == kQuickImageMark ? "a quick image" : "the full image");
      }
    // With $PAVER_VULKAN_VALIDATION=1, what the layer said about the window's device.
    for (const std::string& message : window.context()->validation_messages())
      std::fprintf(stderr, "paver-studio: Vulkan validation: %s\n", message.c_str());
    return runner ? runner->exit_code() : 0;
  } catch (const paver::InputError& e) {
    std::fprintf(stderr, "paver-studio: error: %s\n", paver::printable_cut(e.what(), paver::kMaxMessageBytes).c_str());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "paver-studio: %s\n", paver::printable_cut(e.what(), paver::kMaxMessageBytes).c_str());
    return 1;
  }
}
