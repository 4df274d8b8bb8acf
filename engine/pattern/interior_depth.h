#pragma once
// Elements at least this many D from the boundary count as interior: nearer it, a triangulation's
// valence is the hull's, not the lattice's. The report's valence share and the adaptive pattern's
// defect healing both use it.

namespace paver {

inline constexpr double kInteriorDepth = 2;

}  // namespace paver
