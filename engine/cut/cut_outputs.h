#pragma once
// What a cut leaves behind, written the same way by `paver run --subtract` and the studio's Cut
// metal: cut.stl (the metal) and cut.3mf (the metal as a printable model, with the stones), and
// report.json's `cut` section.
#include "cut/seat_rules.h"
#include "cut/solid_cut.h"
#include "design/design.h"
#include "elements/elements.h"

#include <nlohmann/json_fwd.hpp>

#include <atomic>
#include <filesystem>
#include <string>
#include <vector>

namespace paver {

// The cut and its production rules, made the same way by `paver run --subtract` and the studio's
// Cut metal: the metal (cut_pavement), the seats checked (check_seats, at the options' seat depth)
// and what to tell the user.
struct CheckedCut {
  CutSolid solid;
  SeatCheck seats;
  std::vector<std::string> problems;  // a broken rule's verdict line each (seat_rule_problems): NOT OK
  std::string stand_out;              // the culets standing out behind, or empty (a warning)
};
CheckedCut cut_and_check(const SurfaceMap& map, const Elements& stones, const CutOptions& options,
                         const SeatRules& rules, Units units);

// Writes the files of io/mesh_formats.h's cut_file_names into `folder`: cut.stl and cut.3mf, the
// metal alone (beads joined), for the slicer to slice as it is, and stones.3mf, `stones` alone
// (no beads: the metal holds them), for the setter; `custom` is the design's custom shape, for
// stones that use it. Throws InputError naming the file; Interrupted when `stop` becomes true.
void write_cut_files(const std::filesystem::path& folder, const CutSolid& cut, const Elements& stones,
                     const ShapeMesh* custom, Units units, const std::atomic<bool>* stop = nullptr);

// report.json's `cut`: the cutter and thickness, counts, volumes in mm^3 and the metal's weight in
// every alloy of report/metal_weight.h.
nlohmann::json cut_json(const CutSolid& cut, CutterKind cutter, double thickness, Units units);

// A warning when the stones reach deeper below the surface than the metal is thick (their culets
// then stand out of its back: on a ring, against the finger); empty when they do not.
std::string stones_stand_out_warning(const CutSolid& cut, double thickness, Units units);

}  // namespace paver
