// The designer's deletions: pattern and added elements by id, refilled ones by where they were
// (the refill places anew after any edit upstream, so its ids are not stable).
#include "elements/element_deletion.h"

#include <gtest/gtest.h>

namespace paver {
namespace {

Elements row_of(const std::vector<int>& ids) {
  Elements e;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    e.push_back(ElementKind::Vertex, int(i), 0, {double(i), 0}, {double(i), 0, 0}, {0, 0, 1}, 1.0, ShapeKind::Sphere);
    e.id.back() = ids[i];
  }
  return e;
}

TEST(ElementDeletion, PatternAndAddedByIdRefilledByPlace) {
  constexpr int kFirstRefill = 50;
  Elements e = row_of({0, 1, 50, 51, kFirstAddedId});  // at u = 0, 1, 2, 3, 4
  ElementEdits edits;
  edits.deleted.push_back({1, {99, 99}});             // by id: the point does not matter
  edits.deleted.push_back({50, {3.2, 0}});            // a refilled id: the one whose footprint covers (3.2, 0)
  edits.deleted.push_back({kFirstAddedId, {0, 0}});   // the designer's own, by id
  edits.deleted.push_back({77, {10, 0}});             // a refilled one that is no longer anywhere near
  edits.deleted.push_back({8, {0, 0}});               // a pattern id that is not there
  EXPECT_EQ(delete_elements(e, edits, kFirstRefill), 2);
  EXPECT_EQ(e.id, (std::vector<int>{0, 50}));
}

}  // namespace
}  // namespace paver
