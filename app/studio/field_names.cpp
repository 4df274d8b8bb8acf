#include "field_names.h"

#include "design/design_keys.h"

#include <algorithm>
#include <cctype>

namespace paver::studio {
namespace {

// The first index in a key ("elements.edge[2].t" -> "2"), or "".
std::string first_index(std::string_view key) {
  const std::size_t open = key.find('['), close = key.find(']');
  return open == std::string_view::npos || close == std::string_view::npos || close < open
             ? ""
             : std::string(key.substr(open + 1, close - open - 1));
}

bool is_key_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '[' || c == ']'; }

}  // namespace

std::string studio_field(std::string_view key) {
  // "placement.offset[1]" and "elements.edge[0].cell_edges[1]" are edited in their key's field.
  std::string shape(key);
  const DesignKey* row = find_design_key(shape);
  while (!row && shape.ends_with("]") && shape.rfind('[') != std::string::npos) {
    shape.erase(shape.rfind('['));
    row = find_design_key(shape);
  }
  if (!row) return "";
  std::string where(row->studio);
  if (const std::size_t hash = where.find('#'); hash != std::string::npos) where.replace(hash, 1, first_index(key));
  return where;
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
