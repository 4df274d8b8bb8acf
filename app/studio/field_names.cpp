#include "field_names.h"

#include "design/solver_parameters.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <utility>

namespace paver::studio {
namespace {

// A key without its indices ("elements.edge[2].t" -> "elements.edge[].t") and its first index.
std::pair<std::string, std::string> without_indices(std::string_view key) {
  std::string shape, first;
  for (std::size_t i = 0; i < key.size(); ++i) {
    if (key[i] != '[') {
      shape += key[i];
      continue;
    }
    const std::size_t close = key.find(']', i);
    if (close == std::string_view::npos) return {std::string(key), ""};
    if (first.empty()) first = key.substr(i + 1, close - i - 1);
    shape += "[]";
    i = close;
  }
  return {shape, first};
}

struct Field {
  std::string_view key;     // indices written as []
  std::string_view where;   // "#" stands for the first index
};

// The studio's labels, as the panels draw them (elements_panel.cpp, pattern_panel.cpp,
// single_elements_panel.cpp); keys under a prefix ending in '.' or '[]' share one place.
constexpr std::array kFields = {
    Field{"pattern.spacing", "Pattern > D (spacing)"},
    Field{"pattern.tessellation", "Pattern > tessellation"},
    Field{"pattern.topology", "Pattern > topology"},
    Field{"pattern.operators[]", "Pattern > edge operators > #"},
    Field{"elements.vertex.scale", "Elements > V-elements > s"},
    Field{"elements.vertex.shape", "Elements > V-elements > shape"},
    Field{"elements.vertex.enabled", "Elements > V-elements > enabled"},
    Field{"elements.edge[].t", "Elements > E-element # > t"},
    Field{"elements.edge[].scale", "Elements > E-element # > s"},
    Field{"elements.edge[].shape", "Elements > E-element # > shape"},
    Field{"elements.edge[].cell_edges[]", "Elements > E-element # > cell edges"},
    Field{"elements.gap", "Elements > Stones (jewellery) > gap"},
    Field{"elements.margin", "Elements > Stones (jewellery) > edge margin"},
    Field{"elements.beads.scale", "Elements > Stones (jewellery) > bead size"},
    Field{"elements.custom_shape", "Elements > Custom shape"},
    Field{"placement.offset[]", "Pattern > Placement > offset"},
    Field{"placement.rotation_deg", "Pattern > Placement > rotation"},
    Field{"placement.scale", "Pattern > Placement > scale"},
    Field{"placement.align", "Pattern > Placement > rows along axis"},
    Field{"placement.fit_offset", "Pattern > Placement > fit offset"},
    Field{"edits.moved", "Elements > Single stones > edits (moved)"},
    Field{"edits.moved[].", "Elements > Single stones > edits (moved)"},
    Field{"edits.added", "Elements > Single stones > edits (added)"},
    Field{"edits.added[].", "Elements > Single stones > edits (added)"},
    Field{"edits.deleted[].", "Elements > Single stones > edits (deleted)"},
    Field{"guidance[].", "Pattern > Guidance brush > dab #"},
};

bool is_key_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '[' || c == ']'; }

}  // namespace

std::string studio_field(std::string_view key) {
  const auto [shape, index] = without_indices(key);
  if (shape.starts_with("solver.")) {
    const SolverParameter* p = find_solver_parameter(std::string_view(shape).substr(7));
    return p ? "Optimize > " + std::string(p->label) + " (" + std::string(p->name) + ")" : "";
  }
  for (const Field& f : kFields) {
    const bool prefix = f.key.ends_with('.');
    if (prefix ? !shape.starts_with(f.key) : shape != f.key) continue;
    std::string where(f.where);
    if (const std::size_t hash = where.find('#'); hash != std::string::npos) where.replace(hash, 1, index);
    return where;
  }
  return "";
}

std::string in_studio_words(std::string_view message) {
  std::string out;
  std::size_t i = 0;
  while (i < message.size()) {
    const std::size_t open = message.find('\'', i);
    if (open == std::string_view::npos) break;
    const std::size_t close = message.find('\'', open + 1);
    if (close == std::string_view::npos) break;
    const std::string_view key = message.substr(open + 1, close - open - 1);
    const bool looks_like_key = !key.empty() && std::all_of(key.begin(), key.end(), is_key_char);
    const std::string field = looks_like_key ? studio_field(key) : "";
    out += message.substr(i, open - i);
    out += field.empty() ? std::string(message.substr(open, close + 1 - open)) : field + " (" + std::string(key) + ")";
    i = close + 1;
  }
  out += message.substr(i);
  return out;
}

}  // namespace paver::studio
