// The report panel: the quality of the initial pavement, of the paper's method alone and of the
// final result, the solver's iterations and stop reason, times, the edit-to-result latency, and
// a histogram of the nearest-neighbour ratios.
#include "panels.h"

#include "core/contact_rule.h"
#include "core/number_text.h"
#include "report/bill_of_stones.h"

#include "../studio.h"

#include <algorithm>
#include <cstdio>
#include <string>

namespace paver::studio {
namespace {

void quality_table(const Pavement& p) {
  if (!ImGui::BeginTable("quality", 4, ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit))
    return;
  ImGui::TableSetupColumn("");
  ImGui::TableSetupColumn("initial");
  ImGui::TableSetupColumn("paper's method");
  ImGui::TableSetupColumn("final");
  ImGui::TableHeadersRow();
  const PavementQuality* q[3] = {&p.before, &p.paper, &p.after};
  const auto row = [&](const char* name, auto&& value, const char* format) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(name);
    for (const PavementQuality* column : q) {
      ImGui::TableNextColumn();
      ImGui::Text(format, value(*column));
    }
  };
  row("elements", [](const PavementQuality& x) { return x.elements; }, "%ld");
  row("contact violations", [](const PavementQuality& x) { return x.contact_violations; }, "%ld");
  row("worst overlap", [](const PavementQuality& x) { return x.worst_overlap; }, "%.3g");
  row("min clearance", [](const PavementQuality& x) { return x.min_clearance; }, "%.3g");
  row("fill", [](const PavementQuality& x) { return x.fill; }, "%.3f");
  row("NN ratio min", [](const PavementQuality& x) { return x.neighbor_ratio.min; }, "%.3f");
  row("NN ratio p5", [](const PavementQuality& x) { return x.neighbor_ratio.p5; }, "%.3f");
  row("NN ratio median", [](const PavementQuality& x) { return x.neighbor_ratio.median; }, "%.3f");
  row("NN ratio p95", [](const PavementQuality& x) { return x.neighbor_ratio.p95; }, "%.3f");
  row("NN ratio cv", [](const PavementQuality& x) { return x.neighbor_ratio.cv; }, "%.3f");
  row("spring dev. median", [](const PavementQuality& x) { return x.spring_deviation_median; }, "%.3f");
  row("spring dev. p95", [](const PavementQuality& x) { return x.spring_deviation_p95; }, "%.3f");
  row("boundary crossings", [](const PavementQuality& x) { return x.boundary_crossings; }, "%ld");
  row("coverage", [](const PavementQuality& x) { return x.coverage; }, "%.3f");
  // Measured for the final pavement only (Measure::Counts before it): "-" rather than a false 0.
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  ImGui::TextUnformatted("spacing~curvature");
  for (const PavementQuality* column : q) {
    ImGui::TableNextColumn();
    if (column->structure_measured)
      ImGui::Text("%.3f", column->spacing_curvature_spearman);
    else
      ImGui::TextUnformatted("-");
  }
  ImGui::EndTable();
}

// What a jeweller orders from: stones by shape and size in mm, carats for round brilliants, and the
// beads (report/bill_of_stones.h, the same figures as stones.csv).
void bill_table(const Pavement& p, const BillOfStones& bill) {
  if (ImGui::BeginTable("stones", 5, ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) {
    for (const char* name : {"shape", "size (mm)", "count", "ct each", "ct"}) ImGui::TableSetupColumn(name);
    ImGui::TableHeadersRow();
    for (const StoneRow& row : bill.rows) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(std::string(enum_name(row.shape)).c_str());
      ImGui::TableNextColumn();
      ImGui::Text("%.2f", row.diameter_mm);
      ImGui::TableNextColumn();
      ImGui::Text("%ld", row.count);
      ImGui::TableNextColumn();
      // As stones.csv writes them.
      ImGui::TextUnformatted(row.carat_each ? carat_each_text(*row.carat_each).c_str() : "-");
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(row.carat_each ? carat_total_text(row.carat_total).c_str() : "-");
    }
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted("total");
    ImGui::TableNextColumn();
    ImGui::TableNextColumn();
    ImGui::Text("%ld", bill.count);
    ImGui::TableNextColumn();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(bill.weighed() ? carat_total_text(bill.carat_total).c_str() : "-");
    ImGui::EndTable();
  }
  if (p.design.elements.beads.enabled) ImGui::Text("beads (shared prongs): %zu", p.beads.size());
  help_marker("Carats for round brilliant diamonds (gem): the trade's chart from 0.75 to 6.5 mm, in proportion "
              "to the diameter cubed beyond it (docs/stones.md). Other shapes are counted, not weighed.");
}

}  // namespace

void report_panel(const Studio& s) {
  const PavementResult& r = s.doc.result;
  if (!r.pavement) {
    ImGui::TextWrapped(s.doc.surface.map ? "No pavement yet: it appears when the run finishes."
                                         : "Open a surface (File) to pave it.");
    return;
  }
  const Pavement& p = *r.pavement;
  if (r.revision != s.doc.revision) ImGui::TextColored(ImVec4(1, 0.8f, 0.3f, 1), "for an earlier design: re-running");
  // The verdict first, as `paver run` prints it and report.json carries it (report/verdict.h).
  if (r.verdict.ok) {
    ImGui::TextColored(ImVec4(0.45f, 0.85f, 0.45f, 1), "verdict: ok");
  } else {
    ImGui::TextColored(ImVec4(1, 0.45f, 0.4f, 1), "verdict: NOT OK");
    for (const std::string& problem : r.verdict.problems) ImGui::BulletText("%s", problem.c_str());
  }
  help_marker("Ok when no pair of elements is closer than the sum of their radii plus the gap (checked over "
              "all pairs), none crosses the surface's edge, the pattern is not torn and not mostly bare.");
  // Short unwrapped lines: ImGui wraps after a '.', which split numbers ("0." / "000736").
  ImGui::Text("contact: %s", count_text(p.after.contact_violations, "violation", "violations").c_str());
  const std::string unit(enum_name(p.design.units));
  ImGui::Text("closest pair: %.3g %s free (gap %.3g)", p.after.min_clearance, unit.c_str(), p.design.elements.gap);
  ImGui::Text("%zu elements: %ld V, %ld E, %ld F", p.elements.size(), p.after.vertex_elements, p.after.edge_elements,
              p.after.face_elements);
  ImGui::Text("%d filled, %d eliminated at the boundary", p.filled, p.eliminated);
  ImGui::Text("pattern: %d points, %d edges; D = %.4g", p.pattern.point_count(), p.pattern.edge_count(),
              p.design.pattern.spacing);
  ImGui::Text("solver: %d iterations, %s", p.solve.iterations, std::string(enum_name(p.solve.reason)).c_str());
  ImGui::Text("last max step %.3g, %d pull-backs", p.solve.last_max_step, p.solve.strays_pulled_back);
  ImGui::Text("contacts: %s, %s", count_text(p.resolution.rounds, "round", "rounds").c_str(),
              count_text(p.resolution.contact_springs, "spring", "springs").c_str());
  ImGui::Text("%s, %d removed", count_text(p.resolution.solver_iterations, "iteration", "iterations").c_str(),
              p.resolution.removed);
  ImGui::Text("run %.0f ms (solver %.0f ms)", r.run_ms, p.solve.milliseconds);
  if (r.latency_ms >= 0)
    ImGui::Text("edit to result on screen: %.0f ms", r.latency_ms);
  help_marker("From the last design change to the frame that showed its final, optimized pavement; it "
              "includes the wait for a dragged slider to rest.");

  section("Bill of stones");
  bill_table(p, r.bill);

  section("Quality");
  quality_table(p);

  section("Nearest-neighbour ratio");
  const float peak = r.ratio_histogram.empty() ? 1.0f : *std::max_element(r.ratio_histogram.begin(), r.ratio_histogram.end());
  char overlay[64];
  std::snprintf(overlay, sizeof overlay, "%.2f .. %.2f (1 = touching)", kHistogramMin, kHistogramMax);
  ImGui::PlotHistogram("##ratios", r.ratio_histogram.data(), int(r.ratio_histogram.size()), 0, overlay, 0.0f,
                       peak * 1.1f, ImVec2(ImGui::GetContentRegionAvail().x, 110));
  char contact[200];
  std::snprintf(contact, sizeof contact,
                "Per element: distance to the nearest other element over the sum of their radii plus the "
                "gap (%.4g). Below 1 violates the contact rule; values outside the range are counted in "
                "the end bins.",
                p.design.elements.gap);
  help_marker(contact);

  section("Stages (ms)");
  for (const auto& [stage, ms] : p.timings) ImGui::BulletText("%s: %.1f", stage.c_str(), ms);
  for (const auto& [stage, ms] : s.doc.surface.timings) ImGui::BulletText("%s: %.1f (surface)", stage.c_str(), ms);
}

}  // namespace paver::studio
