#pragma once
// The contact rule counted the plainest way: a loop over ALL pairs of elements with no spatial
// structure, independent of the solver's grids, for tests to check the pipeline's figures against.
#include "elements/elements.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <limits>

namespace paver::test {

struct AllPairs {
  long violations = 0;  // pairs closer than r_i + r_j + gap
  double min_clearance = std::numeric_limits<double>::infinity();
};

inline AllPairs all_pairs(const Elements& e, double gap) {
  AllPairs out;
  for (size_t i = 0; i < e.size(); ++i)
    for (size_t j = i + 1; j < e.size(); ++j) {
      const double d = glm::length(e.position[i] - e.position[j]);
      const double radii = 0.5 * e.diameter[i] + 0.5 * e.diameter[j];
      if (d < radii + gap) ++out.violations;
      out.min_clearance = std::min(out.min_clearance, d - radii);
    }
  return out;
}

}  // namespace paver::test
