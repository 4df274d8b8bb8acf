// The studio's single-element edits, as the views and the script call them: what each records in
// design.edits, what it refuses and why, and that a new pattern layout clears edits that would
// otherwise name other elements.
#include "element_editing.h"
#include "document.h"
#include "map_frame.h"

#include "core/input_error.h"
#include "elements/element_ids.h"
#include "io/design_io.h"
#include "input_error_assertions.h"
#include "surface_maps.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace paver::studio {
namespace {

const Pavement& gems() {
  static const Pavement pavement = [] {
    Design design = load_design(test::source_dir() / "assets/designs/pendant_tri_gems.json");
    return make_pavement(*test::bundled_map("pendant"), design);
  }();
  return pavement;
}

std::size_t first_of(const Pavement& p, ElementKind kind, bool from_pattern) {
  for (std::size_t i = 0; i < p.elements.size(); ++i)
    if (p.elements.kind[i] == kind && (p.elements.source[i] >= 0) == from_pattern) return i;
  ADD_FAILURE() << "no such element";
  return 0;
}

TEST(ElementEditing, PinningAnEdgeElementPinsBothEndsOfItsEdge) {
  const Pavement& p = gems();
  const std::size_t e = first_of(p, ElementKind::Edge, true);
  const Design pinned = with_pinned(p.design, p, p.elements.id[e], true);
  ASSERT_EQ(pinned.edits.moved.size(), 2u);
  const int edge = p.elements.source[e];
  EXPECT_EQ(pinned.edits.moved[0].id, p.pattern.edge_a[std::size_t(edge)]);
  EXPECT_EQ(pinned.edits.moved[1].id, p.pattern.edge_b[std::size_t(edge)]);
  EXPECT_EQ(pinned.edits.moved[0].uv, p.points[std::size_t(pinned.edits.moved[0].id)]);
  EXPECT_NE(pinned.pattern.topology, Topology::Auto) << "ids name one pattern: the topology is fixed";
  // Unpinning keeps where it was put and lets it relax.
  const Design unpinned = with_pinned(pinned, p, p.elements.id[e], false);
  EXPECT_FALSE(unpinned.edits.moved[0].pinned);
}

// The views mark what is held: exactly the elements is_pinned says, the designer's added ones too.
TEST(ElementEditing, HeldElementsAreThePinnedAndTheAdded) {
  const Pavement& p = gems();
  EXPECT_TRUE(held_elements(p.design, p).empty());
  const std::size_t e = first_of(p, ElementKind::Edge, true);
  Design design = with_pinned(p.design, p, p.elements.id[e], true);
  const std::vector<std::size_t> held = held_elements(design, p);
  ASSERT_FALSE(held.empty());
  EXPECT_NE(std::find(held.begin(), held.end(), e), held.end()) << "the pinned edge element";
  for (std::size_t i = 0; i < p.elements.size(); ++i)
    EXPECT_EQ(std::find(held.begin(), held.end(), i) != held.end(), is_pinned(design, p, p.elements.id[i])) << i;
}

TEST(ElementEditing, DragMovesByTheOffsetAndHolds) {
  const Pavement& p = gems();
  const std::size_t v = first_of(p, ElementKind::Vertex, true);
  const int id = p.elements.id[v];
  const Design dragged = with_dragged(p.design, p, id, {0.5, -0.25});
  ASSERT_EQ(dragged.edits.moved.size(), 1u);
  EXPECT_EQ(dragged.edits.moved[0].id, id);
  EXPECT_EQ(dragged.edits.moved[0].uv, p.points[std::size_t(id)] + glm::dvec2(0.5, -0.25));
  EXPECT_TRUE(dragged.edits.moved[0].pinned);
  // Dragging again moves the same entry.
  const Design twice = with_dragged(dragged, p, id, {0.5, 0});
  EXPECT_EQ(twice.edits.moved.size(), 1u);
}

TEST(ElementEditing, AddAndDeleteRecordIdsThatAreNeverReused) {
  const Pavement& p = gems();
  int first = -1, second = -1;
  Design design = with_added_element(p.design, p, {1, 2}, &first);
  EXPECT_EQ(first, kFirstAddedId);
  design = with_added_element(design, p, {3, 4}, &second);
  EXPECT_EQ(second, kFirstAddedId + 1);
  const std::size_t v = first_of(p, ElementKind::Vertex, true);
  design = without_element(design, p, p.elements.id[v]);
  ASSERT_EQ(design.edits.deleted.size(), 1u);
  EXPECT_EQ(design.edits.deleted[0].uv, p.elements.uv[v]);
}

// The first edit on a fitted pavement keeps the fitted offset in the design (a fit is not made under
// edits): the edited design lays the same lattice, less the deleted stone.
TEST(ElementEditing, AnEditKeepsTheFittedOffsetInTheDesign) {
  Design design = load_design(test::source_dir() / "assets/designs/pendant_tri_gems.json");
  design.placement.fit_offset = true;
  const SurfaceMap& map = *test::bundled_map("pendant");
  const Pavement fitted = make_pavement(map, design);
  ASSERT_TRUE(fitted.offset_fit.has_value());
  ASSERT_NE(fitted.offset_fit->chosen.shift_in_cells, glm::dvec2(0)) << "the case: the fit moved the lattice";
  const std::size_t v = first_of(fitted, ElementKind::Vertex, true);
  const Design edited = without_element(design, fitted, fitted.elements.id[v]);
  EXPECT_FALSE(edited.placement.fit_offset);
  EXPECT_EQ(edited.placement.offset, fitted.offset_fit->chosen.offset);
  const Pavement after = make_pavement(map, edited);
  EXPECT_EQ(after.deletions_missed, 0);
  std::size_t same = 0;
  for (std::size_t i = 0; i < fitted.elements.size(); ++i)
    same += std::count(after.elements.position.begin(), after.elements.position.end(), fitted.elements.position[i]) > 0;
  EXPECT_GE(double(same), 0.9 * double(fitted.elements.size())) << "the stones around stay where they were";
  EXPECT_EQ(std::count(after.elements.uv.begin(), after.elements.uv.end(), fitted.elements.uv[v]), 0)
      << "the deleted stone is gone";
}

// The first edit on a ring whose rows auto laid along it names that way in the design: auto is not
// chosen under edits (they name one lattice's elements), so the edit stays on the lattice it was
// made on.
TEST(ElementEditing, AnEditKeepsTheBandsRowsInTheDesign) {
  Design design;
  design.pattern.tessellation = Tessellation::Triangle;
  design.elements.gap = 0.1;
  set_stone_size(design, 3);
  const SurfaceMap& map = *test::bundled_map("ring_band");
  const Pavement laid = make_pavement(map, design);
  ASSERT_TRUE(laid.band_closure && !laid.band_closure->rows_across) << "the case: auto laid the rows along";
  const std::size_t v = first_of(laid, ElementKind::Vertex, true);
  const Design edited = without_element(design, laid, laid.elements.id[v]);
  EXPECT_EQ(edited.placement.band_rows, BandRows::Along);
  const Pavement after = make_pavement(map, edited);
  EXPECT_EQ(after.deletions_missed, 0);
  EXPECT_EQ(after.elements.size() + 1, laid.elements.size()) << "the same ring, less the deleted stone";
}

// A box takes the elements whose centres it holds, whichever way it was drawn.
TEST(ElementEditing, ABoxSelectsTheElementsWhoseCentresItHolds) {
  const Pavement& p = gems();
  const glm::dvec2 a(-3.0, -2.5), b(2.5, 3.0);
  const std::vector<int> ids = elements_in_box(p, a, b);
  std::size_t inside = 0;
  for (std::size_t i = 0; i < p.elements.size(); ++i) {
    const glm::dvec2 uv = p.elements.uv[i];
    const bool in = uv.x >= a.x && uv.x <= b.x && uv.y >= a.y && uv.y <= b.y;
    inside += in;
    EXPECT_EQ(std::find(ids.begin(), ids.end(), p.elements.id[i]) != ids.end(), in) << "element " << p.elements.id[i];
  }
  EXPECT_GT(inside, 10u) << "a box that holds a few";
  EXPECT_EQ(ids.size(), inside);
  EXPECT_EQ(elements_in_box(p, b, a), ids) << "corners in any order";
  EXPECT_TRUE(elements_in_box(p, {100, 100}, {101, 101}).empty());
}

// In a 2D view turned like the 3D view, a Shift+drag box takes the elements drawn inside the
// rectangle on screen, not those of the map's axis-aligned box through its corners.
TEST(ElementEditing, ABoxInATurnedViewSelectsWhatTheScreenShowsInIt) {
  const Pavement& p = gems();
  render::MapView view;
  view.centre = glm::vec2(0.3f, -0.2f), view.half_height = 8, view.turn = 0.6f;
  const MapFrame frame{ImVec2(20, 30), ImVec2(800, 500), view};
  const ImVec2 from(300, 180), to(560, 400);
  // The frame maps pixels to map points and back.
  for (const ImVec2 pixel : {from, to, ImVec2(20, 30), ImVec2(700, 100)}) {
    const ImVec2 back = frame.to_screen(frame.to_map(pixel));
    EXPECT_NEAR(back.x, pixel.x, 1e-3);
    EXPECT_NEAR(back.y, pixel.y, 1e-3);
  }
  const std::vector<int> ids = elements_in_box(p, frame.to_map(from), frame.to_map(to), view.turn);
  std::size_t inside = 0, only_in_the_axis_box = 0;
  const std::vector<int> axis_box = elements_in_box(p, frame.to_map(from), frame.to_map(to));
  for (std::size_t i = 0; i < p.elements.size(); ++i) {
    const ImVec2 at = frame.to_screen(p.elements.uv[i]);
    const bool in = at.x >= from.x && at.x <= to.x && at.y >= from.y && at.y <= to.y;
    inside += in;
    const bool taken = std::find(ids.begin(), ids.end(), p.elements.id[i]) != ids.end();
    EXPECT_EQ(taken, in) << "element " << p.elements.id[i] << " at " << at.x << ", " << at.y;
    only_in_the_axis_box += !in && std::find(axis_box.begin(), axis_box.end(), p.elements.id[i]) != axis_box.end();
  }
  EXPECT_GT(inside, 10u) << "a box that holds a few";
  EXPECT_GT(only_in_the_axis_box, 0u) << "the case does not tell a turned box from an axis-aligned one";
}

TEST(ElementEditing, RefusalsSayWhatToDoInstead) {
  const Pavement& p = gems();
  EXPECT_NE(test::error_of([&] { with_pinned(p.design, p, 99999999, true); }).find("is not in the pavement on screen"),
            std::string::npos);
  // A refilled element is placed anew on every run: it cannot be held by id. (The pendant needs no
  // refill, so one of its vertex elements is made one.)
  Pavement refilled = p;
  const std::size_t v = first_of(p, ElementKind::Vertex, true);
  refilled.elements.source[v] = -1;
  refilled.elements.id[v] = first_refill_id(p.pattern) + 3;
  EXPECT_NE(test::error_of([&] { with_dragged(p.design, refilled, refilled.elements.id[v], {1, 0}); })
                .find("placed by the refill, which places anew on every run"),
            std::string::npos);
  // ... but it can be deleted (by where it is).
  EXPECT_EQ(without_element(p.design, refilled, refilled.elements.id[v]).edits.deleted.size(), 1u);
  Design adaptive = p.design;
  adaptive.pattern.topology = Topology::Adaptive;
  EXPECT_NE(test::error_of([&] { with_added_element(adaptive, p, {0, 0}); }).find("adaptive"), std::string::npos);
  Design no_vertices = p.design;
  no_vertices.elements.vertex.enabled = false;
  EXPECT_NE(test::error_of([&] { with_added_element(no_vertices, p, {0, 0}); }).find("vertex elements are off"),
            std::string::npos);
}

TEST(ElementEditing, ANewPatternLayoutClearsTheEditsAndUndoBringsThemBack) {
  const Pavement& p = gems();
  Document doc;
  doc.design = p.design;
  ASSERT_TRUE(change_design(doc, with_pinned(doc.design, p, p.elements.id[first_of(p, ElementKind::Vertex, true)], true)));
  ASSERT_FALSE(doc.design.edits.empty());
  Design finer = doc.design;
  finer.pattern.spacing *= 0.9;
  ASSERT_TRUE(change_design(doc, finer));
  EXPECT_TRUE(doc.design.edits.empty());
  EXPECT_NE(doc.messages.status.find("element edits cleared"), std::string::npos);
  // A design that brings its own edits (a file opened) keeps them, whatever its layout.
  Document other;
  Design loaded = p.design;
  loaded.pattern.spacing *= 1.1;
  loaded.edits.deleted.push_back({3, {0, 0}});
  ASSERT_TRUE(change_design(other, loaded));
  EXPECT_EQ(other.design.edits.deleted.size(), 1u);
  // A change that keeps the layout keeps them.
  ASSERT_TRUE(undo(doc));
  Design smaller = doc.design;
  smaller.elements.vertex.scale = 0.5;
  ASSERT_TRUE(change_design(doc, smaller));
  EXPECT_FALSE(doc.design.edits.empty());
}

}  // namespace
}  // namespace paver::studio
