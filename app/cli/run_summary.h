#pragma once
// The summary `paver run` prints on stdout: the verdict first, then the surface, the map, the
// pattern and every choice made, the optimizer, the elements and the bill of stones, the cut, the
// quality figures, the timings and the files written.
#include "pipeline/run_pipeline.h"

#include <nlohmann/json.hpp>

#include <string>

namespace paver::cli {

struct SummaryContext {
  std::string surface;        // as given on the command line
  std::string backend;        // the backend asked for (auto, cpu, vulkan)
  std::string device;         // the device it chose, if any
  nlohmann::json cut;         // report.json's "cut" section, when --subtract cut the metal
  std::string written;        // the files written, "placements.csv, stones.csv, ..."
  std::string out;            // the output folder
};

// Prints the summary; returns whether the verdict is ok.
bool print_run_summary(const PipelineResult& result, const SummaryContext& context);

}  // namespace paver::cli
