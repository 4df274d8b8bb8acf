#include "mesh/reader_support.h"

#include "mesh/mesh_messages.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <system_error>
#include <utility>

namespace paver::mesh_detail {

void check_mesh_counts(const std::string& source, long long vertices, long long faces) {
  const auto millions = [](long long n) { return std::to_string(n / 1'000'000) + " million"; };
  if (faces > kMaxMeshFaces)
    fail(source, "has " + std::to_string(faces) + " faces; Paver reads surfaces of up to " + millions(kMaxMeshFaces) +
                     " faces: decimate the mesh first (a pavement needs far fewer)");
  if (vertices > kMaxMeshVertices)
    fail(source, "has " + std::to_string(vertices) + " vertices; Paver reads surfaces of up to " +
                     millions(kMaxMeshVertices) + " vertices: decimate the mesh first (a pavement needs far fewer)");
}

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

std::string lowercase(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = char(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

bool equals_lowercase(std::string_view text, std::string_view lower) {
  if (text.size() != lower.size()) return false;
  for (size_t i = 0; i < text.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(text[i])) != lower[i]) return false;
  return true;
}

void split_tokens(std::string_view line, std::vector<std::string_view>& tokens) {
  tokens.clear();
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_space(line[i])) ++i;
    const size_t start = i;
    while (i < line.size() && !is_space(line[i])) ++i;
    if (i > start) tokens.push_back(line.substr(start, i - start));
  }
}

bool LineReader::next(std::string_view& line) {
  if (pos_ >= text_.size()) return false;
  const size_t end = std::min(text_.find('\n', pos_), text_.size());
  line = trim(text_.substr(pos_, end - pos_));
  pos_ = end + 1;
  ++number_;
  return true;
}

bool TokenReader::next(std::string_view& token) {
  while (index_ >= tokens_.size()) {
    std::string_view line;
    if (!lines_.next(line)) return false;
    split_tokens(line, tokens_);
    index_ = 0;
  }
  token = tokens_[index_++];
  return true;
}

namespace {

// from_chars takes no '+'; "+-1" stays refused.
bool strip_plus(std::string_view& token) {
  if (!token.empty() && token.front() == '+') {
    token.remove_prefix(1);
    if (!token.empty() && token.front() == '-') return false;
  }
  return !token.empty();
}

}  // namespace

bool parse_integer(std::string_view token, long long& value) {
  if (!strip_plus(token)) return false;
  const char* end = token.data() + token.size();
  const auto result = std::from_chars(token.data(), end, value);
  return result.ec == std::errc() && result.ptr == end;
}

bool parse_double(std::string_view token, double& value) {
  if (!strip_plus(token)) return false;
  const char* end = token.data() + token.size();
  const auto result = std::from_chars(token.data(), end, value);
  if (result.ptr != end) return false;
  if (result.ec == std::errc::result_out_of_range) value = std::strtod(std::string(token).c_str(), nullptr);
  else if (result.ec != std::errc()) return false;
  return true;
}

CoordinateReader::CoordinateReader(std::string source, const char* one, const char* many, int first_number)
    : source_(std::move(source)), one_(one), many_(many), first_number_(first_number) {}

std::string CoordinateReader::item_name(long long item) const {
  return std::string(one_) + " " + std::to_string(item + first_number_) + " (counting from " +
         std::to_string(first_number_) + ")";
}

double CoordinateReader::text(std::string_view token, int line, long long item) {
  double value = 0;
  if (!parse_double(token, value))
    fail(source_, at_line(line) + quoted(token) + " is not a number; vertex coordinates must be numbers");
  if (!std::isfinite(value)) note_nonfinite(at_line(line), token.substr(0, 40), item);
  return value;
}

double CoordinateReader::binary(double value, std::uint64_t offset, long long item) {
  const auto shown = [value] {
    std::ostringstream out;
    out << value;
    return out.str();
  };
  if (!std::isfinite(value)) note_nonfinite(at_byte(offset), shown(), item);
  return value;
}

void CoordinateReader::note_nonfinite(const std::string& place, std::string_view shown, long long item) {
  // Counted per item, so an item with several bad coordinates counts once.
  if (item == last_nonfinite_item_) return;
  last_nonfinite_item_ = item;
  if (nonfinite_items_++ > 0) return;
  first_nonfinite_ = place + item_name(item) + " has a non-finite coordinate " + quoted(shown);
}

void CoordinateReader::finish() const {
  if (nonfinite_items_ == 0) return;
  fail(source_, first_nonfinite_ + "; " +
                    count_of(nonfinite_items_, (std::string(one_) + " has").c_str(),
                             (std::string(many_) + " have").c_str()) +
                    " NaN or infinite coordinates: fix them in the modelling tool and export again");
}

std::uint64_t load_unsigned(std::string_view bytes, size_t at, size_t size, bool big_endian) {
  std::uint64_t value = 0;
  for (size_t i = 0; i < size; ++i)
    value |= std::uint64_t(static_cast<unsigned char>(bytes[at + (big_endian ? size - 1 - i : i)])) << (8 * i);
  return value;
}

float load_float(std::string_view bytes, size_t at, bool big_endian) {
  return std::bit_cast<float>(static_cast<std::uint32_t>(load_unsigned(bytes, at, 4, big_endian)));
}

double load_double(std::string_view bytes, size_t at, bool big_endian) {
  return std::bit_cast<double>(load_unsigned(bytes, at, 8, big_endian));
}

}  // namespace paver::mesh_detail
