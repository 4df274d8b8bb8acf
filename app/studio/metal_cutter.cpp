#include "metal_cutter.h"

#include "available_memory.h"

#include "io/output_guard.h"
#include "io/stl_unit_warning.h"
#include "core/number_text.h"
#include "report/metal_weight.h"
#ifdef PAVER_WITH_CGAL
#include "cut/cut_outputs.h"
#include "cut/finger_side.h"
#endif

#include <cstdio>
#include <mutex>

namespace paver::studio {

struct MetalCutter::Shared {
  std::mutex mutex;
  bool busy = false;
  std::optional<CutOutcome> outcome;
};

bool MetalCutter::available() {
#ifdef PAVER_WITH_CGAL
  return true;
#else
  return false;
#endif
}

void MetalCutter::start(std::shared_ptr<const SurfaceMap> map, std::shared_ptr<const Pavement> pavement,
                        std::shared_ptr<const ShapeMesh> custom, const CutRequest& request, const std::filesystem::path& folder) {
  auto shared = std::make_shared<Shared>();
  shared->busy = true;
  shared_ = shared;
  jobs_.start([shared, map = std::move(map), pavement = std::move(pavement), custom = std::move(custom), request,
               folder](std::stop_token stop) {
    CutOutcome outcome;
#ifdef PAVER_WITH_CGAL
    try {
      std::atomic<bool> stopped{false};
      std::stop_callback on_stop(stop, [&] { stopped = true; });
      const Units units = pavement->design.units;
      std::optional<FingerSide> ring;
      if (request.inside_diameter_mm > 0)
        ring = check_finger_side(*map, request.inside_diameter_mm / millimetres_per_unit(units), request.thickness,
                                 "inside diameter " + significant_text(request.inside_diameter_mm, 4) + " mm");
      const auto rule = [](double value) { return value > 0 ? std::optional<double>(value) : std::nullopt; };
      const SeatRules rules{rule(request.culet_clearance), rule(request.seat_wall), rule(request.table_height)};
      const CutOptions cut_options{.cutter = CutterKind::Seat, .thickness = request.thickness, .custom = custom.get(),
                                   .stop = &stopped, .beads = &pavement->beads, .finger_side = ring ? &*ring : nullptr,
                                   .seat_depth = request.seat_depth};
      refuse_cut_beyond_memory(pavement->elements, cut_options, app::available_memory_bytes());
      const CheckedCut checked = cut_and_check(*map, pavement->elements, cut_options, rules, units);
      const CutSolid& cut = checked.solid;
      make_output_folder(folder);
      write_cut_files(folder, cut, pavement->elements, custom.get(), units, &stopped);
      const double mm = millimetres_per_unit(units);
      const double mm3 = cut.volume * mm * mm * mm;
      char text[256];
      std::snprintf(text, sizeof text, "wrote %s/cut.stl, cut.3mf and stones.3mf: %d seats, metal %.4g mm3, %.2f g of 18k gold, "
                    "%.0f ms", folder.string().c_str(), cut.cutters, mm3,
                    metal_grams(cut.volume, units, jewellery_alloys()[1]), cut.milliseconds);
      std::string said = checked.problems.empty() ? text : std::string("NOT OK: ") + text;
      for (const std::string& problem : checked.problems) said += "; " + problem;
      for (const std::string& warning : {checked.stand_out, stl_unit_warning(units, {"cut.stl"})})
        if (!warning.empty()) said += "; warning: " + warning;
      outcome = {true, said};
    } catch (const std::exception& e) {
      outcome = {false, std::string("cut metal: ") + e.what()};
    }
#else
    (void)map, (void)pavement, (void)custom, (void)request, (void)folder, (void)stop;
    outcome = {false, "cut metal: this studio was built without CGAL (-DPAVER_WITH_CGAL=OFF)"};
#endif
    std::lock_guard lock(shared->mutex);
    shared->busy = false;
    shared->outcome = std::move(outcome);
  });
}

bool MetalCutter::busy() const {
  if (!shared_) return false;
  std::lock_guard lock(shared_->mutex);
  return shared_->busy;
}

bool MetalCutter::has_outcome() const {
  if (!shared_) return false;
  std::lock_guard lock(shared_->mutex);
  return shared_->outcome.has_value();
}

std::optional<CutOutcome> MetalCutter::take_outcome() {
  jobs_.reap();
  if (!shared_) return std::nullopt;
  std::lock_guard lock(shared_->mutex);
  std::optional<CutOutcome> outcome = std::move(shared_->outcome);
  shared_->outcome.reset();
  return outcome;
}

}  // namespace paver::studio
