#include "metal_cutter.h"

#include "available_memory.h"

#include "io/output_guard.h"
#include "io/stl_unit_warning.h"
#include "report/metal_weight.h"
#ifdef PAVER_WITH_CGAL
#include "cut/cut_outputs.h"
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
                        std::shared_ptr<const ShapeMesh> custom, double thickness, const std::filesystem::path& folder) {
  auto shared = std::make_shared<Shared>();
  shared->busy = true;
  shared_ = shared;
  jobs_.start([shared, map = std::move(map), pavement = std::move(pavement), custom = std::move(custom), thickness,
               folder](std::stop_token stop) {
    CutOutcome outcome;
#ifdef PAVER_WITH_CGAL
    try {
      std::atomic<bool> stopped{false};
      std::stop_callback on_stop(stop, [&] { stopped = true; });
      const CutOptions cut_options{.cutter = CutterKind::Seat, .thickness = thickness, .custom = custom.get(),
                                   .stop = &stopped, .beads = &pavement->beads};
      refuse_cut_beyond_memory(pavement->elements, cut_options, app::available_memory_bytes());
      const CutSolid cut = cut_pavement(*map, pavement->elements, cut_options);
      make_output_folder(folder);
      write_cut_files(folder, cut, pavement->elements, custom.get(), pavement->design.units, &stopped);
      const double mm = millimetres_per_unit(pavement->design.units);
      const double mm3 = cut.volume * mm * mm * mm;
      char text[256];
      std::snprintf(text, sizeof text, "wrote %s/cut.stl, cut.3mf and stones.3mf: %d seats, metal %.4g mm3, %.2f g of 18k gold, "
                    "%.0f ms", folder.string().c_str(), cut.cutters, mm3,
                    metal_grams(cut.volume, pavement->design.units, jewellery_alloys()[1]), cut.milliseconds);
      std::string said = text;
      for (const std::string& warning : {stones_stand_out_warning(cut, thickness, pavement->design.units),
                                         stl_unit_warning(pavement->design.units, {"cut.stl"})})
        if (!warning.empty()) said += "; warning: " + warning;
      outcome = {true, said};
    } catch (const std::exception& e) {
      outcome = {false, std::string("cut metal: ") + e.what()};
    }
#else
    (void)map, (void)pavement, (void)custom, (void)thickness, (void)folder, (void)stop;
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
