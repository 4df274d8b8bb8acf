#pragma once
// Opens a surface in the background through the pipeline's first stages (map_surface_file, which
// `paver run` calls too), with its progress shown and a stop between the map's chunks, so the window
// never freezes, even on a mesh of a million faces; what the studio exports is what `paver run`
// writes for the same surface and design.
#include "background_jobs.h"

#include "pipeline/pavement.h"
#include "map/surface_charts.h"
#include "map/surface_map.h"

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace paver::studio {

struct OpenedSurface {
  std::filesystem::path path;
  std::shared_ptr<const SurfaceMap> map;
  std::vector<std::string> warnings;  // repairs made while loading
  StageTimings timings;               // "load", "parameterize"
};

struct SurfaceLoadOutcome {
  std::optional<OpenedSurface> surface;  // empty on failure
  std::string error;                     // what went wrong, naming the file
  bool input_error = false;              // the file's fault (InputError), not a bug
};

class SurfaceLoader {
public:
  // A load in progress is abandoned. A closed surface is cut into charts across `cut`.
  void start(const std::filesystem::path& path, CutAxis cut = CutAxis::Auto);
  bool busy() const;
  const std::filesystem::path& path() const { return path_; }  // the last one started
  float progress() const;     // 0..1
  std::string stage() const;  // "loading", "mapping (40 / 300 iterations)", ...
  std::optional<SurfaceLoadOutcome> take_outcome();  // once per finished load

  struct Shared;  // state shared with the loading thread

private:
  std::shared_ptr<Shared> shared_;
  std::filesystem::path path_;
  BackgroundJobs jobs_;
};

}  // namespace paver::studio
