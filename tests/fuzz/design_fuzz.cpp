// libFuzzer target for design.json: the text goes through what `paver run --design` does before
// any surface is read (parse, read every key, validate the ranges, check the unit cell, its
// operators and overlaps). InputError is the expected answer to a bad design; any other
// exception, a crash, a sanitizer report or a hang is a finding.
#include "core/input_error.h"
#include "design/design.h"
#include "io/design_io.h"
#include "pipeline/pavement.h"

#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const paver::Design design = paver::design_from_text(text, "fuzz.json");
    paver::validate_design(design, "fuzz.json");
    paver::check_design_cell(design);
  } catch (const paver::InputError&) {
  }
  return 0;
}
