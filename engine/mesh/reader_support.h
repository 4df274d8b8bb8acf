#pragma once
// What the format readers share: walking text by lines and tokens, whole-token number parsing,
// reading vertex coordinates with their checks, and loading binary scalars of either byte order.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace paver::mesh_detail {

// What a surface file may hold, checked before the memory for it is taken: a 10-million-triangle
// scan reads; a file of 60 million repeated faces (10 GB) or one face of 100,000 corners (8 GB in
// the map of its slivers) is refused at once.
inline constexpr long long kMaxMeshFaces = 20'000'000;
inline constexpr long long kMaxMeshVertices = 20'000'000;
inline constexpr std::size_t kMaxPolygonCorners = 1024;

// Throws InputError naming `source` when the counts pass the limits above.
void check_mesh_counts(const std::string& source, long long vertices, long long faces);

bool is_space(char c);
std::string_view trim(std::string_view s);
std::string lowercase(std::string_view s);
// Whether `text` is `lower` (all lowercase) in any case.
bool equals_lowercase(std::string_view text, std::string_view lower);
void split_tokens(std::string_view line, std::vector<std::string_view>& tokens);

// Walks a text one line at a time, each trimmed; line numbers count from 1.
class LineReader {
public:
  explicit LineReader(std::string_view text) : text_(text) {}
  bool next(std::string_view& line);
  int number() const { return number_; }
  size_t offset() const { return pos_; }  // where the next line starts

private:
  std::string_view text_;
  size_t pos_ = 0;
  int number_ = 0;
};

// Whitespace-separated tokens of a text, with the line each is on.
class TokenReader {
public:
  TokenReader(std::string_view text, int first_line) : lines_(text), first_line_(first_line) {}
  bool next(std::string_view& token);
  int line() const { return first_line_ + lines_.number() - 1; }

private:
  LineReader lines_;
  int first_line_;
  std::vector<std::string_view> tokens_;
  size_t index_ = 0;
};

// Whole tokens only ("1x" is not a number); a leading '+' is accepted.
bool parse_integer(std::string_view token, long long& value);
// Accepts "nan" and "inf" (refused later, with the place), and maps overflow to infinity.
bool parse_double(std::string_view token, double& value);

// Vertex coordinates are read in double precision, as written (a binary file's float32 values
// exactly): a facade in survey coordinates (5.4e6 m) read in single precision lost half a metre,
// welding its vertices and flattening its discs. load_surface rounds a surface near the origin
// to float32 as before (mesh_loader.cpp says why). NaN and infinity (a text value beyond
// double's range too) are counted, and finish() refuses the file naming the first one.
class CoordinateReader {
public:
  // `one` and `many` name what holds the coordinates ("vertex", "vertices"); `first_number` is
  // the number of the first one in messages (OBJ counts from 1, the other formats from 0).
  CoordinateReader(std::string source, const char* one, const char* many, int first_number);

  // A coordinate token of item `item` (counting from 0) on line `line`.
  double text(std::string_view token, int line, long long item);
  // A decoded binary value of item `item` at byte `offset`.
  double binary(double value, std::uint64_t offset, long long item);
  // Refuses the file if any coordinate was NaN or infinite.
  void finish() const;

private:
  void note_nonfinite(const std::string& place, std::string_view shown, long long item);
  std::string item_name(long long item) const;

  std::string source_;
  const char* one_;
  const char* many_;
  int first_number_;
  long long nonfinite_items_ = 0;
  long long last_nonfinite_item_ = -1;
  std::string first_nonfinite_;  // "line 4: vertex 2 (counting from 1) has a non-finite coordinate 'nan'"
};

// Unsigned integer of `size` bytes (1, 2, 4 or 8) at `at`; the caller checks the bounds.
std::uint64_t load_unsigned(std::string_view bytes, size_t at, size_t size, bool big_endian);
float load_float(std::string_view bytes, size_t at, bool big_endian);
double load_double(std::string_view bytes, size_t at, bool big_endian);

}  // namespace paver::mesh_detail
