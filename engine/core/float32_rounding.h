#pragma once
// A double rounded to the nearest float32, as a double. Through a volatile float: GCC 12.2's SLP
// vectorizer folds the round trip double -> float -> double away in a loop at -O2 and -O3
// (measured: 0.1 stayed 0.1000000000000000055 instead of becoming 0.100000001490116), which
// would skip the rounding silently.
namespace paver {

inline double rounded_to_float32(double value) {
  volatile float narrow = static_cast<float>(value);
  return narrow;
}

}  // namespace paver
