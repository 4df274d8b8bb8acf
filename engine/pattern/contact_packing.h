#pragma once
// Hard-contact packing on the surface: particles nearer each other than a contact distance are
// pushed apart by a harmonic overlap energy, minimised with FIRE (Bitzek et al. 2006), whose
// inertia carries a push across a whole patch in O(width) steps where plain projection needs
// O(width^2). Particles that no push can fit (the patch is jammed) may be removed, a few per round,
// the most overlapped first. The adaptive pattern packs its particles with it after relaxing them,
// and its optimizer ends with it.
#include "map/boundary_index.h"
#include "map/surface_map.h"
#include "pattern/grade_field.h"

#include <glm/vec2.hpp>

#include <atomic>
#include <vector>

namespace paver {

struct ContactPackingOptions {
  double contact = 0;      // 3D centre distance every pair is pushed out to
  double margin = 0;       // 3D distance every particle keeps from the surface's boundary
  int iterations = 600;    // per round
  int rounds = 1;          // > 1: after a round that left overlaps, remove some particles and go on
  double remove_share = 0.005;  // at most this share of the particles removed per round (at least 1)
  const std::vector<char>* movable = nullptr;  // set: only these particles move (the rest hold a patch's rim)
  const BoundaryIndex* boundary = nullptr;     // set: used instead of one built for the call (reach >= margin)
  // A pair counts as settled from this 3D distance on; 0: contact x (1 - kSettledOverlap). A pavement
  // whose pairs sit just beyond the contact rule is packed with the rule itself here, so that only
  // real overlaps move stones.
  double settled = 0;
  // Graded stones: each particle's contact is `contact` times the grade's contact factor where it
  // is, a pair's the mean of its two (`contact` is the main stone's).
  const GradeField* grade = nullptr;
  // After the descent, the particles pushed out to the margin until every one keeps it (the
  // descent's own push is one step a iteration).
  bool exact_margin = false;
};

struct ContactPackingReport {
  int iterations = 0;        // over all rounds
  int removed = 0;           // particles removed as jammed
  long overlapping_pairs = 0;  // left at the end: pairs nearer than contact (1 - kSettledOverlap)
};

// Relative overlap under which a pair counts as settled: the contact is aimed past the contact
// rule by kContactAim (contact_rule.h), so this still lands a settled pair beyond the rule.
inline constexpr double kSettledOverlap = 5e-4;

// Moves `uv` (particles in the map) on the surface; removes jammed ones from it when rounds > 1.
ContactPackingReport pack_by_contact(const SurfaceMap& map, std::vector<glm::dvec2>& uv,
                                     const ContactPackingOptions& options, const std::atomic<bool>* stop = nullptr);

}  // namespace paver
