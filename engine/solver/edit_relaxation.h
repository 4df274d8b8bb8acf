#pragma once
// The designer's edits on a solved pavement. The design is solved and its collisions resolved as
// if it had no edits; then each moved particle goes where the designer put it and carries its
// neighbourhood along by a smooth falloff (the "soft selection" of modelling tools: no spring in
// reach is compressed or stretched by more than the falloff's slope), added particles appear
// where they were put, and collision resolution runs once more with every particle beyond reach
// held as the design's own run left it. So an edit changes the pavement around it and nowhere
// else, and a saved design reproduces it (the design's run is deterministic, and the edits start
// from it). The paper's solver is not used for this: with a ring of particles held, its global
// term and stray handling tangle the patch inside (measured on the bundled pendant).
#include "pattern/pattern_edits.h"
#include "solver/spring_system.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace paver {

// How far from an edit (x D, in the map) the pavement follows it: a drag of d moves particles
// up to max(kEditReach * D, kEditFalloff * d) away, so the neighbourhood is strained by at most
// about 1.5 / kEditFalloff.
inline constexpr double kEditReach = 3.0;
inline constexpr double kEditFalloff = 4.0;

// Before the design's own run: added particles sit it out (retired), so that it is the unedited
// design's run.
void set_aside_added(SpringSystem& system, const std::vector<EditedParticle>& edited);

// Particles held beyond an edit's reach, with the stray counts to give back.
using HeldParticles = std::vector<std::pair<int, std::uint32_t>>;

// After it: moves the edited particles and their neighbourhoods, holds the designer's pinned and
// added ones (kPinned, for good) and every other particle beyond reach of an edit (until
// release_held: for the resolution around the edits only).
// `carry` false: the neighbourhood stays where it is (only the edited particles move), the way
// tried beside the soft selection on tight pavé (pipeline/pave_once.cpp, apply_edits).
HeldParticles place_edits(SpringSystem& system, const std::vector<EditedParticle>& edited, double spacing,
                          bool carry = true);

// Gives the particles held by place_edits their stray counts back.
void release_held(SpringSystem& system, const HeldParticles& held);

}  // namespace paver
