#pragma once
// The paper's plain trim: no rows along the rims and no spot closing, as every design paved before
// both came on by default for pave (issue 40). For the tests of another stage whose figures (a
// lattice's regular beads, an edit's untouched neighbours, a painted field's spacing) are those of
// the pattern as laid; the edges' own tests, and the CLI's and the bundled designs', run with them.
#include "design/design.h"

#include <string>
#include <vector>

namespace paver::test {

inline Design& with_plain_edges(Design& design) {
  design.elements.rim_rows = RimRows::None;
  design.elements.close_spots = false;
  return design;
}

// Whether every problem of a verdict is one of the edges' (bare spots, an uneven rim): for the
// tests of contact, crossings and fill on surfaces whose spots the closing cannot all reach yet
// (a closed surface's seams, the scanned bands: docs/contact.md has the figures).
inline bool only_edge_problems(const std::vector<std::string>& problems) {
  for (const std::string& p : problems)
    if (p.find(" bare spot") == std::string::npos && !p.starts_with("an uneven rim")) return false;
  return true;
}
// The problems on one line, for a failure's message.
inline std::string all_problems(const std::vector<std::string>& problems) {
  std::string text;
  for (const std::string& p : problems) text += (text.empty() ? "" : "; ") + p;
  return text;
}
// And only bare spots: the rims even.
inline bool only_bare_spots(const std::vector<std::string>& problems) {
  for (const std::string& p : problems)
    if (p.find(" bare spot") == std::string::npos) return false;
  return true;
}

}  // namespace paver::test
