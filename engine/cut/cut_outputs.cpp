#include "cut/cut_outputs.h"

#include "core/number_text.h"
#include "io/element_export.h"
#include "io/mesh_formats.h"
#include "io/shape_table.h"
#include "io/threemf_export.h"
#include "report/metal_weight.h"
#include "report/ring_size.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>

namespace paver {

CheckedCut cut_and_check(const SurfaceMap& map, const Elements& stones, const CutOptions& options,
                         const SeatRules& rules, Units units) {
  CheckedCut checked;
  checked.solid = cut_pavement(map, stones, options);
  const ShapeTable shapes(stones, options.custom, "cut");
  checked.seats = check_seats(stones, shapes, options.cutter, options.thickness, options.finger_side, rules,
                              options.seat_depth);
  checked.problems = seat_rule_problems(checked.seats);
  // On a ring each culet has its own metal to the finger side: the deepest stone need not stand
  // where the metal is thinnest.
  if (!options.finger_side)
    checked.stand_out = stones_stand_out_warning(checked.solid, options.thickness, units);
  else if (checked.seats.least_culet_metal < 0)
    checked.stand_out = "on this ring the stones' culets stand out of the finger side by up to " +
                        significant_text(-checked.seats.least_culet_metal, 3) + " " + std::string(enum_name(units)) +
                        ": use a smaller inside diameter (more metal) or smaller stones";
  return checked;
}

void write_cut_files(const std::filesystem::path& folder, const CutSolid& cut, const Elements& stones,
                     const ShapeMesh* custom, Units units, const std::atomic<bool>* stop) {
  write_mesh_stl(folder / "cut.stl", cut.mesh, "cut solid", stop);
  // The metal alone, so that a slicer slices it as it is: the stones in it were printable objects
  // that stopped PrusaSlicer ("no extrusions in the first layer: gem"); they are in paved.3mf.
  write_pavement_3mf(folder / "cut.3mf", &cut.mesh, Elements{}, units, {.stop = stop}, "metal");
  // The stones alone, in the same frame: what the setter sets into the metal (paved.3mf has the
  // beads too, which the metal holds now), set as deep as their seats were cut.
  write_pavement_3mf(folder / "stones.3mf", nullptr, seated_stones(stones, cut.seat_depth), units,
                     {.custom = custom, .stop = stop});
}

nlohmann::json cut_json(const CutSolid& cut, CutterKind cutter, double thickness, Units units) {
  const double mm = millimetres_per_unit(units), mm3 = mm * mm * mm;
  const double metal = cut.thinnest_metal > 0 ? cut.thinnest_metal : thickness;
  nlohmann::json json = {{"cutter", enum_name(cutter)},
          {"thickness", thickness},
          {"cutters", cut.cutters},
          {"united_cutters", cut.united_cutters},
          {"beads_joined", cut.beads},
          {"shell_volume_mm3", cut.shell_volume * mm3},
          {"volume_mm3", cut.volume * mm3},
          {"removed_mm3", (cut.shell_volume - cut.volume) * mm3},
          {"triangles", cut.mesh.triangles.size()},
          {"closed_manifold_oriented", true},
          // Deeper than the metal is thick, the culets stand out of its back (the finger's side of a ring).
          {"deepest_stone", cut.deepest_stone},
          {"seat_depth", cut.seat_depth},
          {"thinnest_metal", metal},
          {"thickest_metal", cut.thickest_metal > 0 ? cut.thickest_metal : thickness},
          {"stones_stand_out_behind", std::max(0.0, cut.deepest_stone - metal)},
          {"metal", metal_weights_json(cut.volume, units)},
          {"files", cut_file_names()}};
  if (cut.inside_diameter > 0)
    json["ring"] = {{"inside_diameter_mm", cut.inside_diameter * mm},
                    {"nearest_sizes", nearest_ring_sizes_json(cut.inside_diameter * mm)}};
  return json;
}

std::string stones_stand_out_warning(const CutSolid& cut, double thickness, Units units) {
  if (cut.thinnest_metal > 0) thickness = cut.thinnest_metal;  // a ring's metal is thinnest nearest the finger
  if (cut.deepest_stone <= thickness) return {};
  const std::string unit(enum_name(units));
  char text[320];
  std::snprintf(text, sizeof text,
                "the stones reach %.3g %s below the surface and the metal is %.3g %s thick: their culets stand out "
                "of its back by up to %.3g %s; make the metal at least %.3g %s thick, or the stones smaller",
                cut.deepest_stone, unit.c_str(), thickness, unit.c_str(), cut.deepest_stone - thickness, unit.c_str(),
                cut.deepest_stone, unit.c_str());
  return text;
}

}  // namespace paver
