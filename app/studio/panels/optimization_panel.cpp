// The optimization panel: every section 5 parameter with the paper's default and what it does,
// the solver backend, and run / pause / step / reset of the live run.
#include "panels.h"

#include "../studio.h"

#include <cstdio>
#include <string>

namespace paver::studio {
namespace {

struct RealParameter {
  const char* key;
  double SolverParams::*member;
  double lo, hi;
  const char* help;
};

// What design.h says of each parameter; the default is appended from SolverParams{}.
const RealParameter kRealParameters[] = {
    {"c", &SolverParams::c, 0, 1, "Uniform margin, a fraction of D_ab added to every target length (eq. 5). c + m >= 0."},
    {"m", &SolverParams::m, 0, 1, "Curvature-adaptive margin, a fraction of D_ab scaled by the curvature (eq. 5)."},
    {"alpha", &SolverParams::alpha, 0, 50, "k_c(r) = alpha / r^12 - beta / r^6 + gamma (eq. 8): short-range stiffening."},
    {"beta", &SolverParams::beta, 0, 50, "k_c(r) = alpha / r^12 - beta / r^6 + gamma (eq. 8)."},
    {"gamma", &SolverParams::gamma, 0, 10, "k_c(r) = alpha / r^12 - beta / r^6 + gamma (eq. 8): the base stiffness."},
    {"lambda_r", &SolverParams::lambda_r, 0, 1, "Weight of the restoring (spring) force (eq. 13)."},
    {"lambda_l", &SolverParams::lambda_l, 0, 1, "Weight of the local-centric force (eqs. 10-11, 13)."},
    {"lambda_g", &SolverParams::lambda_g, 0, 1,
     "Weight of the global gravity towards the map's centre (eqs. 12-13); 0.001 for curvature-aware designs."},
    {"dt", &SolverParams::dt, 0.001, 1,
     "Step size (eq. 14). The paper uses 0.01 to 0.6 (0.5 on flat surfaces); 0.3 is the largest that measured "
     "stable here (docs/solver.md)."},
    {"threshold", &SolverParams::threshold, 1e-6, 0.1,
     "Convergence: stop when every settled particle moves less than threshold * D in an iteration."},
    {"mu_compressed", &SolverParams::mu_compressed, 0, 2, "Adaptive filter learning rate for compressed springs (eq. 16)."},
    {"mu_stretched", &SolverParams::mu_stretched, 0, 2, "Adaptive filter learning rate for stretched springs (eq. 16)."},
    {"filter_max", &SolverParams::filter_max, 1, 4, "The filter clamps a spring's length to [l_ab, filter_max * l_ab] (eq. 15)."},
};

std::string with_default(const char* help, double value) {
  char text[64];
  std::snprintf(text, sizeof text, "\nDefault: %g", value);
  return help + std::string(text);
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
  ImGui::TextDisabled("using %s%s%s", s.run.choice.name.c_str(), s.run.choice.device.empty() ? "" : " on ",
                      s.run.choice.device.c_str());
  run_controls(s);

  section("Parameters (section 5)");
  Document& doc = s.doc;
  Design d = doc.design;
  const SolverParams defaults;
  ImGui::PushItemWidth(160);
  for (const RealParameter& p : kRealParameters) {
    double& value = d.solver.*p.member;
    const double speed = (p.hi - p.lo) / 500;
    if (ImGui::DragScalar(p.key, ImGuiDataType_Double, &value, float(speed), &p.lo, &p.hi, "%.4g"))
      change_design(doc, d, ImGui::IsItemActive());
    help_marker(with_default(p.help, defaults.*p.member).c_str());
  }
  if (ImGui::DragInt("iterations", &d.solver.iterations, 1, 1, 100000)) change_design(doc, d, ImGui::IsItemActive());
  help_marker(with_default("The iteration limit of the section 5 solver.", defaults.iterations).c_str());
  if (ImGui::DragInt("stray_patience", &d.solver.stray_patience, 0.2f, 0, 1000))
    change_design(doc, d, ImGui::IsItemActive());
  help_marker(with_default("A particle pulled back onto the map this many iterations in a row is retired "
                           "(0 = never).",
                           defaults.stray_patience)
                  .c_str());
  int base = int(d.solver.filter_base);
  const char* bases[] = {"current", "initial"};
  if (ImGui::Combo("filter_base", &base, bases, 2)) {
    d.solver.filter_base = FilterBase(base);
    change_design(doc, d);
  }
  help_marker("Which l_ab the adaptive filter's clamp uses: recomputed every iteration from the current "
              "distortion, or fixed at initialisation; the paper is ambiguous (docs/solver.md).\nDefault: current");
  ImGui::PopItemWidth();
  if (ImGui::Button("defaults")) {
    d.solver = SolverParams{};
    change_design(doc, d);
  }
}

}  // namespace paver::studio
