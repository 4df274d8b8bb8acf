#pragma once
// The subtractive result (paper Fig. 14): the surface thickened into metal (cut/thick_shell.h)
// minus one cutter per element (cut/seat_cutter.h), plus the beads if any, as one closed solid,
// for a printer or caster.
//
// The boolean is CGAL's corefinement with exact constructions (Epeck): cutters that touch are
// united first, cluster by cluster; the disjoint clusters then form one mesh that is subtracted
// in a single difference. CGAL is GPL-3.0-or-later: this part is its own library (engine_cut),
// and a binary that links it is GPL-3.0-or-later (README, "Licence").
#include "cut/finger_side.h"
#include "cut/seat_cutter.h"
#include "elements/elements.h"
#include "map/surface_map.h"

#include <atomic>

namespace paver {

struct CutOptions {
  CutterKind cutter = CutterKind::Seat;
  double thickness = 0;                    // of the metal, surface units
  const ShapeMesh* custom = nullptr;       // the design's custom shape, for CutterKind::Element
  const std::atomic<bool>* stop = nullptr; // checked between cutters and before the difference
  const Elements* beads = nullptr;         // beads (elements/beads.h): metal, joined to the solid
  // A band at a ring size (cut/finger_side.h): its finger side a cylinder, `thickness` then the
  // least metal, checked by check_finger_side before the pavement.
  const FingerSide* finger_side = nullptr;
  // The stones set this deep (their girdles below the surface, seated_stones):
  // the seats cut for them there; 0, at the surface.
  double seat_depth = 0;
};

struct CutSolid {
  SurfaceMesh mesh;             // closed, outward-oriented, not self-intersecting (checked)
  double shell_volume = 0;      // the metal before the cut, surface units^3
  double volume = 0;            // after
  int cutters = 0;
  int united_cutters = 0;       // cutters that touched another and were united with it first
  int beads = 0;                // beads joined to the metal
  double deepest_stone = 0;     // how far the lowest stone reaches below the surface (a gem's culet, set), surface units
  double seat_depth = 0;        // CutOptions::seat_depth: the stones in the cut files are set that deep
  double thinnest_metal = 0;    // the metal's least thickness: `thickness`, or a ring's at its nearest to the finger
  double thickest_metal = 0;    // and its greatest
  double inside_diameter = 0;   // a ring's finger side (surface units); 0 when the metal follows the normals
  double milliseconds = 0;
};

// Throws InputError when the thickness is not positive or the shell folds into itself (the
// surface curves tighter than the thickness), std::runtime_error when the boolean fails (which
// CGAL reports rather than returning a broken solid), Interrupted when options.stop is set.
CutSolid cut_pavement(const SurfaceMap& map, const Elements& elements, const CutOptions& options);

// The memory the cut will take, estimated before it starts from its cutters' triangles: CGAL's
// exact corefinement took 1.78 GB for 3,933 seat cutters and 3.47 GB for 7,033 on the pendant
// (docs/benchmarks.md), about 0.5 MB a seat cutter; other cutters and beads count by their
// triangles against a seat's.
double estimated_cut_bytes(const Elements& elements, const CutOptions& options);
inline constexpr double kCutBytesPerSeatCutter = 0.5e6;

// Refuses (InputError, naming the figures and what to do) a cut whose estimate exceeds
// kCutMemoryShare of `available_bytes` (the memory the machine can give now): a cut past it would
// swap for hours or be killed, leaving nothing. Called before the cut, so that nothing is written.
inline constexpr double kCutMemoryShare = 0.8;
void refuse_cut_beyond_memory(const Elements& elements, const CutOptions& options, double available_bytes);

// How far cutters reach above and below an element, in units of its diameter, so that they pass
// both faces of metal `thickness` thick.
double cutter_reach_above();
double cutter_reach_below(double thickness, double diameter);

}  // namespace paver
