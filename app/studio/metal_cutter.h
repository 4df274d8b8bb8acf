#pragma once
// The studio's "Cut metal": the pavement's metal with its seats (engine/cut, as `paver run
// --subtract` makes it) computed on a thread of its own, so the window keeps drawing for the
// seconds a thousand seats take, then cut.stl and cut.3mf written into the export folder. A new
// cut abandons one in progress.
#include "background_jobs.h"
#include "map/surface_map.h"
#include "pipeline/pavement.h"

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

namespace paver::studio {

// What the designer set for the cut, as `paver run --subtract`'s flags: the metal's thickness,
// how deep the stones are set (--seat-depth), a band's inside diameter in mm (--inside-diameter;
// 0: the metal follows the normals) and the production rules (--culet-clearance, --seat-wall,
// --table-height; 0: no rule), all in surface units but the diameter.
struct CutRequest {
  double thickness = 1;
  double seat_depth = 0;
  double inside_diameter_mm = 0;
  double culet_clearance = 0, seat_wall = 0, table_height = 0;
};

struct CutOutcome {
  bool ok = false;
  std::string message;  // what was written and the metal's weight (NOT OK first when a rule broke), or what went wrong
};

class MetalCutter {
public:
  // Whether this studio was built with the cut (CGAL); without it start() reports why not.
  static bool available();
  // `custom`: the design's custom shape, when a stone uses it (kept alive by the job).
  void start(std::shared_ptr<const SurfaceMap> map, std::shared_ptr<const Pavement> pavement,
             std::shared_ptr<const ShapeMesh> custom, const CutRequest& request, const std::filesystem::path& folder);
  bool busy() const;
  bool has_outcome() const;                  // finished and not yet taken
  std::optional<CutOutcome> take_outcome();  // once per finished cut

  struct Shared;

private:
  std::shared_ptr<Shared> shared_;
  BackgroundJobs jobs_;
};

}  // namespace paver::studio
