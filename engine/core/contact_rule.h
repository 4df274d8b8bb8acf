#pragma once
// When two elements collide: the one rule that the design check, collision resolution, refill,
// the quality report and the colour scale all use. Elements with diameters d_a and d_b whose
// centres are `distance` apart collide when
//     distance < (d_a + d_b) / 2 + gap,
// with `gap` >= 0 the user's required clearance between footprints (elements.gap, surface units).
// Exact: no tolerance. The solver aims a little beyond it (kContactAim) so that float32 rounding
// in the particle positions cannot land a pair on the wrong side.
namespace paver {

// Centre distance two elements need: their radii plus the gap.
inline double contact_distance(double diameter_a, double diameter_b, double gap = 0) {
  return 0.5 * (diameter_a + diameter_b) + gap;
}

inline bool elements_collide(double distance, double diameter_a, double diameter_b, double gap) {
  return distance < contact_distance(diameter_a, diameter_b, gap);
}

// Free space between two footprints: centre distance less both radii (negative = overlap).
inline double clearance_between(double distance, double diameter_a, double diameter_b) {
  return distance - contact_distance(diameter_a, diameter_b);
}

// Contact springs and refill aim this much beyond the contact distance (relative), far above
// float32 rounding (6e-8) and far below anything a jeweller could see.
inline constexpr double kContactAim = 1e-3;

}  // namespace paver
