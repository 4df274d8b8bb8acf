#pragma once
// The one chooser above the pass: every automatic choice of a design (pattern.topology auto,
// placement.band_rows auto on a band, placement.fit_offset, placement.cut_axis auto on a closed
// surface) paves its candidates with the pass (pipeline/pave_once.h) and keeps the best by the one
// ranking of pavements, paves_better (report/verdict.h). Only best_of compares pavements.
#include "pipeline/pavement.h"

#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace paver {

// One candidate of a choice: how to pave it, given the best pavement so far (null for the first),
// and whether it is worth paving at all given the best so far (empty: always).
struct Candidate {
  std::string name;  // "across", "adaptive", "x": its timing is "<name>_tried" when it is dropped
  std::function<Pavement(const Pavement* best)> pave;
  std::function<bool(const Pavement& best)> worth_trying;
};

struct Choice {
  Pavement kept;
  int kept_index = -1;
  std::vector<long> elements;  // per candidate: the elements its pavement kept; -1 when not paved
  std::vector<std::optional<PavementQuality>> quality;  // per candidate: its final figures, when paved
  // The stages of the candidates paved and dropped, "<name>_tried" each, in candidate order.
  StageTimings dropped;
};

// Paves the candidates in order and keeps the best by paves_better, the first among equals. The
// first candidate is always paved; no other once `stop` is asked.
Choice best_of(const std::vector<Candidate>& candidates, const std::atomic<bool>* stop);

// The options a candidate is paved with when its choice is announced as one stage: no stage
// names of its own (the observer and the pattern hook stay).
PavementOptions quietly(const PavementOptions& options);

}  // namespace paver
