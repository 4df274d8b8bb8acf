#include "elements/stone_grade.h"

namespace paver {

int grade_stones(const SurfaceMap& map, const GradeField& field, Elements& elements) {
  std::vector<std::size_t> graded;
  std::vector<glm::dvec2> uv;
  for (std::size_t i = 0; i < elements.size(); ++i)
    if (elements.kind[i] == ElementKind::Vertex && elements.diameter[i] == field.main())
      graded.push_back(i), uv.push_back(elements.uv[i]);
  const std::vector<double> shares = grade_shares(map, field, uv);
  int changed = 0;
  for (std::size_t k = 0; k < graded.size(); ++k) {
    const double stone = field.stone_for(shares[k]);
    if (stone == elements.diameter[graded[k]]) continue;
    elements.diameter[graded[k]] = stone;
    ++changed;
  }
  return changed;
}

}  // namespace paver
