#pragma once
// report.json: what a run made and how good it is, as numbers (counts, map quality, timings).
#include "pipeline/pavement.h"
#include "map/surface_map.h"

#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

namespace paver {

struct RunInfo {
  std::string surface_path;
  std::string design_source;         // design file, or "defaults"
  bool spacing_derived = false;      // spacing came from the surface size
  std::vector<std::string> region;   // the surface's parts paved (--region), all when empty
};

// What the CLI's summary and the report count.
struct PavementCounts {
  long pattern_edges = 0;            // real edges of the trimmed pattern
  long virtual_edges = 0;            // bracing edges
  long boundary_crossing_edges = 0;
  long vertex_elements = 0, edge_elements = 0, face_elements = 0;
  long pattern_faces = 0;  // faces of the trimmed pattern that F-elements were placed in (0 without them)
  long retired_particles = 0;
};
PavementCounts count_pavement(const Pavement& pavement);

// report.json's `beads`: {"enabled": false}, or the count and the smallest and largest diameter
// in mm (diameter_mm_min, diameter_mm_max; 0 without beads) with the design's scale.
nlohmann::json beads_json(const Pavement& pavement);
// report.json "edits": the designer's pinned, moved, added and deleted elements.
nlohmann::json edits_json(const Pavement& pavement);

nlohmann::json make_run_report(const RunInfo& info, const SurfaceMap& map, const Pavement& pavement,
                               const StageTimings& timings);

}  // namespace paver
