// The optimization panel: every section 5 parameter with the paper's default and what it does,
// the solver backend, and run / pause / step / reset of the live run.
#include "panels.h"

#include "../studio.h"

#include <algorithm>
#include <variant>
#include <string>

namespace paver::studio {
namespace {

// The tooltip: what it does in words, its unit, its default and its design.json key, all from
// the parameter table.
std::string tooltip(const SolverParameter& p) {
  return std::string(p.help) + "\nUnit: " + std::string(p.unit) + "\nDefault: " + default_text(p) +
         "\nIn design.json: solver." + std::string(p.name);
}

// One widget for a parameter of the table; true when the user changed it. Dragging stays in the
// slider's range (inside the valid range, tested); Ctrl+click can type any value, which
// change_design validates like a design file.
bool parameter_widget(const SolverParameter& p, SolverParams& solver) {
  // Words first, the paper's symbol after, so that a designer and a reader of the paper both find it.
  const std::string label = std::string(p.label) + " (" + std::string(p.name) + ")";
  if (const auto* real = std::get_if<double SolverParams::*>(&p.member)) {
    double& value = solver.**real;
    double lo = p.slider.min;
    const double hi = p.slider.max;
    // m may go negative only as far as c allows (eq. 5: c + m >= 0).
    if (p.name == "m") lo = std::max(lo, -solver.c);
    const float speed = float((hi - lo) / 500);
    return ImGui::DragScalar(label.c_str(), ImGuiDataType_Double, &value, speed, &lo, &hi, "%.4g");
  }
  if (const auto* integer = std::get_if<int SolverParams::*>(&p.member)) {
    const float speed = p.slider.max - p.slider.min > 5000 ? 1.0f : 0.2f;  // counts: one per pixel at most
    return ImGui::DragInt(label.c_str(), &(solver.**integer), speed, int(p.slider.min), int(p.slider.max));
  }
  FilterBase& base = solver.*std::get<FilterBase SolverParams::*>(p.member);
  int index = int(base);
  const char* names[] = {"current", "initial"};
  if (!ImGui::Combo(label.c_str(), &index, names, 2)) return false;
  base = FilterBase(index);
  return true;
}

void run_controls(Studio& s) {
  const RunState state = s.live.state();
  if (ImGui::Button("Run")) run_now(s);
  ImGui::SameLine();
  if (ImGui::Button(state == RunState::Paused ? "Resume" : "Pause")) toggle_pause(s);
  ImGui::SameLine();
  if (ImGui::Button("Step")) step_run(s);
  ImGui::SameLine();
  if (ImGui::Button("Reset")) reset_run(s);
  ImGui::SetNextItemWidth(120);
  ImGui::SliderInt("iterations per step", &s.run.step_iterations, 1, 200);
  ImGui::Checkbox("run on every change", &s.run.auto_run);
  help_marker("Every design change re-runs the pavement (after a slider rests for 200 ms).");
  const char* names[] = {"idle", "running", "paused", "finished"};
  ImGui::Text("%s, iteration %d", names[int(state)], s.live.iteration());
}

}  // namespace

void optimization_panel(Studio& s) {
  section("Solver");
  int backend = s.run.backend == "cpu" ? 0 : s.run.backend == "vulkan" ? 1 : 2;
  const int before = backend;
  ImGui::RadioButton("CPU", &backend, 0);
  ImGui::SameLine();
  ImGui::RadioButton("Vulkan", &backend, 1);
  ImGui::SameLine();
  ImGui::RadioButton("auto", &backend, 2);
  if (backend != before) set_backend(s, backend == 0 ? "cpu" : backend == 1 ? "vulkan" : "auto");
  if (s.run.choice.name == "auto")
    ImGui::TextDisabled("using %s from %d particles, the CPU below", s.run.choice.device.c_str(),
                        app::kAutoGpuLeastParticles);
  else
    ImGui::TextDisabled("using %s%s%s", s.run.choice.name.c_str(), s.run.choice.device.empty() ? "" : " on ",
                        s.run.choice.device.c_str());
  run_controls(s);

  section("Parameters (section 5)");
  Document& doc = s.doc;
  Design d = doc.design;
  ImGui::PushItemWidth(ImGui::GetFontSize() * 7);  // room for the labels in words
  // What a designer reaches for first; the paper's forces and filter fold away under Advanced.
  const auto basic = [](const SolverParameter& p) {
    return p.name == "c" || p.name == "m" || p.name == "iterations" || p.name == "dt" || p.name == "threshold";
  };
  for (const bool advanced : {false, true}) {
    if (advanced && !ImGui::CollapsingHeader("Advanced: the paper's forces, filter and strays")) break;
    for (const SolverParameter& p : solver_parameters()) {
      if (basic(p) == advanced) continue;
      if (parameter_widget(p, d.solver)) change_design(doc, d, ImGui::IsItemActive());
      help_marker(tooltip(p).c_str());
    }
  }
  ImGui::PopItemWidth();
  if (ImGui::Button("defaults")) {
    d.solver = SolverParams{};
    change_design(doc, d);
  }
}

}  // namespace paver::studio
