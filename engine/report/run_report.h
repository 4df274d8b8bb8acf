#pragma once
// report.json: what a run made and how good it is, as numbers (counts, map quality, timings).
#include "pipeline/pavement.h"
#include "map/surface_map.h"

#include <nlohmann/json_fwd.hpp>

#include <string>

namespace paver {

struct RunInfo {
  std::string surface_path;
  std::string design_source;         // design file, or "defaults"
  bool spacing_derived = false;      // spacing came from the surface size
};

nlohmann::json make_run_report(const RunInfo& info, const SurfaceMap& map, const Pavement& pavement,
                               const StageTimings& timings);

}  // namespace paver
