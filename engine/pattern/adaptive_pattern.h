#pragma once
// The adaptive pattern: where the map distorts the surface more than spring relaxation can absorb
// (a nearly closed head flattened to a disc), a lattice piles up in one place and tears in
// another. Instead the design's pattern is grown on the surface: particles relaxed to the
// design's spacing (particle_relaxation.h) and connected by their surface triangulation (tri),
// or by its dual (hex: a honeycomb whose faces are the triangulation's vertices). The pattern is
// regular wherever the surface allows and has a few point defects elsewhere: 5- and 7-valent
// vertices (tri), pentagons and heptagons (hex), like the twelve pentagons of a football.
#include "design/design.h"
#include "map/surface_map.h"
#include "pattern/grade_field.h"
#include "pattern/particle_relaxation.h"
#include "pattern/pattern.h"
#include "pattern/unit_cell.h"

#include <atomic>
#include <string>

namespace paver {

// Empty when the design can take an adaptive pattern; otherwise why not, in words. Supported:
// tri and hex without edge operators, placement scale 1, and edge elements that sit on every
// edge symmetrically (t and 1 - t both present), since a defect has no lattice directions.
std::string adaptive_pattern_unsupported(const Design& design);

struct AdaptivePattern {
  Pattern pattern;
  RelaxationReport relaxation;
};

// Grows the design's pattern over the map at spacing design.pattern.spacing (> 0), with eq. 5's
// growth (solver.c, solver.m) in the density and, for graded stones, the grade's (`grade`, the
// design's field on this map: make_grade_field). `cell` is the design's cell at that spacing.
AdaptivePattern build_adaptive_pattern(const SurfaceMap& map, const UnitCell& cell, const Design& design,
                                       const std::atomic<bool>* stop = nullptr, const GradeField* grade = nullptr);

// How far the particles keep from the boundary: the largest element's radius (with a rim grade,
// the smallest stone's: the rim row is of those) and the edge margin (none on a closed surface).
double particle_boundary_margin(const SurfaceMap& map, const Design& design, const GradeField* grade);

}  // namespace paver
