#pragma once
// What a number field takes (issue 45: a value refused without a word reverted silently): the
// text as typed is read whole ("0-5" is no number, not 0), checked against the field's range, and
// refused with one line phrased for that field: what was typed, why not, and the range to give.
// The panels' typed_number shows the line under the field, outlined, and keeps the text typed.
#include "design/design_keys.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace paver::studio {

struct NumberRule {
  ValueRange range;       // open bounds refuse the bound itself
  std::string unit{};       // "mm", or empty
  std::string hi_reason{};  // why the upper bound, said after a value too large: "D = stone + gap ..."
  std::string hint{};       // said after the range: "0 = derive from the surface"

  // The key's range and note, from the one table of design keys (design/design_keys.h).
  static NumberRule of(Key key, std::string unit = {});
  // Tightened to below `hi` (when that is lower), with the reason a larger value is refused.
  NumberRule& below(double hi, std::string reason);
};

struct TypedNumber {
  std::optional<double> value;  // none when refused
  std::string problem;          // the line to show when refused
};

// `text` as typed into the field named `label`.
TypedNumber read_typed_number(std::string_view label, std::string_view text, const NumberRule& rule);

// The range a rule takes, as the refusal says it: "a value above 0 mm", "from 0 to 12.5".
std::string range_text(const NumberRule& rule);

// Refusals the fields made this frame, for the status line (and a script's log): taken once.
void post_refusal(std::string line);
std::vector<std::string> take_refusals();

}  // namespace paver::studio
