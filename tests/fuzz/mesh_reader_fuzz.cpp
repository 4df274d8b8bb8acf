// libFuzzer target for one mesh reader (chosen at build time by PAVER_FUZZ_READER: read_obj,
// read_off, read_ply or read_stl). Every file a user or a custom shape can name goes through the
// reader, then the surface checks (make_surface) and the custom-shape normalisation: the two
// things a read file becomes. InputError is the expected answer to bad bytes; any other exception,
// a crash, a sanitizer report, a hang or runaway memory is a finding.
#include "core/input_error.h"
#include "elements/element_shape.h"
#include "mesh/mesh_loader.h"
#include "mesh/obj_reader.h"
#include "mesh/off_reader.h"
#include "mesh/ply_reader.h"
#include "mesh/stl_reader.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  paver::PolygonSoup soup;
  try {
    soup = paver::PAVER_FUZZ_READER(bytes, "fuzz");
  } catch (const paver::InputError&) {
    return 0;
  }
  try {
    (void)paver::custom_shape_from_soup(soup, "fuzz shape");
  } catch (const paver::InputError&) {
  }
  try {
    (void)paver::make_surface(std::move(soup.positions), soup.polygons, "fuzz");
  } catch (const paver::InputError&) {
  }
  return 0;
}
