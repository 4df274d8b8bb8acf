#pragma once
// When two elements collide: the one rule that the design check, collision resolution, the
// quality report and the colour scale all use. Elements with diameters d_a and d_b whose centres
// are `distance` apart collide when distance < kContactFactor (d_a + d_b) / 2.
// The factor forgives 1% of a contact (the project's historical rule); issue 10 replaces it by an
// exact rule with the user's gap, here, and moves it into solver/solver_contract.h when the GPU
// resolves collisions.
namespace paver {

inline constexpr double kContactFactor = 0.99;

inline double contact_distance(double diameter_a, double diameter_b) { return 0.5 * (diameter_a + diameter_b); }

inline bool elements_collide(double distance, double diameter_a, double diameter_b) {
  return distance < kContactFactor * contact_distance(diameter_a, diameter_b);
}

}  // namespace paver
