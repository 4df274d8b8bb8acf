#include "pipeline/pavement.h"

#include "elements/element_shape.h"

namespace paver {

const Elements& stones_and_beads(const Pavement& pavement, Elements& storage,
                                 std::vector<std::array<std::uint8_t, 3>>* colours) {
  if (pavement.beads.size() == 0) return pavement.elements;
  storage = pavement.elements;
  storage.append(pavement.beads);
  if (colours) colours->resize(storage.size(), kind_colour(ElementKind::Bead));
  return storage;
}

const SurfaceMap& map_for_topology(const SurfaceMap& map, Topology topology) {
  return map.seamless && topology != Topology::Adaptive ? *map.seamless : map;
}

std::string band_annulus_reason(const SurfaceMap& map, const Pavement& pavement) {
  if (!is_band(map) || pavement.seamless) return "";
  if (!map.seamless_unavailable.empty()) return map.seamless_unavailable;
  return pavement.design.pattern.topology == Topology::Lattice
             ? "the seamless lattice tore or left bare patches; the lattice on the annulus did better"
             : "the adaptive pattern grows on the annulus map";
}

const SurfaceMap& pavement_map(const SurfaceMap& map, const Pavement& pavement) {
  return pavement.seamless && map.seamless ? *map.seamless : map;
}

}  // namespace paver
