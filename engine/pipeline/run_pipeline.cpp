#include "pipeline/run_pipeline.h"

#include "core/input_error.h"
#include "io/output_guard.h"
#include "pipeline/run_outputs.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <utility>

namespace paver {
namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

bool is_file_source(const std::string& source) { return source != "defaults" && source != "studio"; }

}  // namespace

PipelineResult run_pipeline(PipelineRequest request) {
  PipelineResult result;
  const Design& design = request.design;
  validate_design(design, request.design_source);
  result.info = RunInfo{request.surface_path.string(), request.design_source, design.pattern.spacing <= 0};
  if (uses_custom_shape(design.elements))
    result.custom_shape = std::make_shared<const ShapeMesh>(load_custom_shape(design.elements.custom_shape));

  // Refuse before any work if an output would replace an input.
  std::vector<std::filesystem::path> outputs;
  if (request.out) {
    outputs = run_output_paths(*request.out, request.stl);
    outputs.insert(outputs.end(), request.extra_outputs.begin(), request.extra_outputs.end());
    std::vector<std::filesystem::path> inputs = {request.surface_path, design.elements.custom_shape};
    if (is_file_source(request.design_source)) inputs.push_back(request.design_source);
    refuse_overwriting_inputs(inputs, outputs);
  }

  if (request.map) {
    result.map = std::move(request.map);
    result.timings = std::move(request.map_timings);
  } else {
    MappedSurface mapped = map_surface_file(request.surface_path, request.progress);
    result.map = std::move(mapped.map);
    result.warnings = std::move(mapped.warnings);
    result.timings = std::move(mapped.timings);
  }

  result.pavement = make_pavement(*result.map, design, request.pavement);
  result.timings.insert(result.timings.end(), result.pavement.timings.begin(), result.pavement.timings.end());
  result.counts = count_pavement(result.pavement);

  if (request.out) {
    auto t0 = Clock::now();
    write_run_files(*request.out, result.pavement, {.custom = result.custom_shape.get(), .stl = request.stl});
    result.timings.emplace_back("export", ms_since(t0));
    if (request.write_extras) request.write_extras(result, result.timings);
    write_run_report(*request.out, result.info, *result.map, result.pavement, result.timings);
  }
  return result;
}

}  // namespace paver
