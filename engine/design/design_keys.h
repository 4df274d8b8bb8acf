#pragma once
// Every design.json key, described once (as PAVER_SOLVER_PARAMETERS is for the solver, whose rows
// this table takes in): its dotted path, type, valid range, unit, one line of help, the `paver run`
// flag that sets it and where the studio edits it. From it come the design.json reader and writer,
// the range checks, the CLI's key flags and the list of flags given, the studio's field names in
// messages and the key table of docs/design_file.md (checked by a test). The C++ field each key
// reads and writes is named once too, in visit_keys below; a message that names a key names it
// through key_path or key_and_flag, never by spelling it.
#include "design/design.h"
#include "design/solver_parameters.h"

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace paver {

// The keys in design.json's order. An array of objects (pattern.operators) comes before the keys
// of its items (pattern.operators[].op, ...).
enum class Key {
  units,
  pattern_tessellation,
  pattern_spacing,
  pattern_bracing,
  pattern_operators,
  operator_op,
  operator_from,
  operator_to,
  operator_offset,
  operator_virtual,
  cell_a1,
  cell_a2,
  cell_vertices,
  cell_vertex_at,
  cell_edges,
  cell_edge_from,
  cell_edge_to,
  cell_edge_offset,
  cell_edge_virtual,
  pattern_topology,
  vertex_enabled,
  vertex_scale,
  vertex_shape,
  elements_edge,
  edge_t,
  edge_scale,
  edge_shape,
  edge_cell_edges,
  face_enabled,
  face_scale,
  face_shape,
  custom_shape,
  allow_overlap,
  gap,
  margin,
  rim_rows,
  close_spots,
  fill_sizes,
  grade_by,
  grade_smallest,
  grade_width,
  grade_point,
  beads_enabled,
  beads_scale,
  beads_min_diameter,
  beads_over,
  placement_offset,
  rotation_deg,
  placement_scale,
  band_rows,
  cut_axis,
  align,
  fit_offset,
#define PAVER_SOLVER_KEY(type, name, ...) solver_##name,
  PAVER_SOLVER_PARAMETERS(PAVER_SOLVER_KEY)
#undef PAVER_SOLVER_KEY
  edits_moved,
  moved_id,
  moved_uv,
  moved_pinned,
  edits_deleted,
  deleted_id,
  deleted_uv,
  edits_added,
  added_id,
  added_uv,
  guidance,
  dab_uv,
  dab_radius,
  dab_strength,
};

// What a key holds, as design.json writes it.
enum class KeyType {
  Number,   // a double
  Integer,  // an int
  Bool,
  Text,     // a string (a path)
  Choice,   // a string naming one of an enum's values
  Pair,     // [x, y] of numbers
  IntPair,  // [i, j] of integers
  IntList,  // [i, ...] of integers
  NumberList,  // [x, ...] of numbers
  Objects,  // an array of objects, whose fields are keys of their own
};

struct DesignKey {
  Key key;
  std::string_view path;        // "elements.margin"; an array item's field: "pattern.operators[].from"
  KeyType type;
  ValueRange range;             // a number's (each one's, in a pair or list); any() for the rest
  std::string_view range_note;  // what the range means, after it in a refusal: "0 = derive from the surface"
  std::string_view unit;        // "surface units", "degrees", "x D"; empty when it has none
  std::string_view help;        // one line: docs/design_file.md's table, the flag's help
  std::string_view flag;        // the `paver run` flag that sets it ("margin" for --margin); empty: none
  std::string_view studio;      // where the studio edits it ("Elements > Stones (jewellery) > edge margin")
  bool required = false;        // an array item's field that must be given (an edit's id and uv)
  std::string_view choices;     // a Choice's values, quoted ("\"tri\", \"grid\", \"hex\"")
  std::string_view default_text;  // as design.json writes it ("0", "\"auto\"", "[0, 0]")
};

std::span<const DesignKey> design_keys();
const DesignKey& design_key(Key key);
// A key by its path, with or without indices ("elements.edge[2].t" finds elements.edge[].t).
const DesignKey* find_design_key(std::string_view path);

// The key's path, with an array item's index where it has one: "elements.margin",
// key_path(Key::edge_t, 2) = "elements.edge[2].t".
std::string key_path(Key key, std::optional<std::size_t> index = std::nullopt);
// "elements.margin (--margin)": for a message about a key that a file or a flag may have set.
std::string key_and_flag(Key key);

// Calls visit(key, field) for every key of `design` (Design or const Design) in the table's order;
// an Objects key's field is the vector of its items, whose own keys visit_item_keys visits.
template <class D, class Visit>
  requires std::is_same_v<std::remove_const_t<D>, Design>
void visit_keys(D& d, Visit&& visit) {
  visit(Key::units, d.units);
  visit(Key::pattern_tessellation, d.pattern.tessellation);
  visit(Key::pattern_spacing, d.pattern.spacing);
  visit(Key::pattern_bracing, d.pattern.bracing);
  visit(Key::pattern_operators, d.pattern.operators);
  visit(Key::cell_a1, d.pattern.cell.a1);
  visit(Key::cell_a2, d.pattern.cell.a2);
  visit(Key::cell_vertices, d.pattern.cell.vertices);
  visit(Key::cell_edges, d.pattern.cell.edges);
  visit(Key::pattern_topology, d.pattern.topology);
  visit(Key::vertex_enabled, d.elements.vertex.enabled);
  visit(Key::vertex_scale, d.elements.vertex.scale);
  visit(Key::vertex_shape, d.elements.vertex.shape);
  visit(Key::elements_edge, d.elements.edge);
  visit(Key::face_enabled, d.elements.face.enabled);
  visit(Key::face_scale, d.elements.face.scale);
  visit(Key::face_shape, d.elements.face.shape);
  visit(Key::custom_shape, d.elements.custom_shape);
  visit(Key::allow_overlap, d.elements.allow_overlap);
  visit(Key::gap, d.elements.gap);
  visit(Key::margin, d.elements.margin);
  visit(Key::rim_rows, d.elements.rim_rows);
  visit(Key::close_spots, d.elements.close_spots);
  visit(Key::fill_sizes, d.elements.fill_sizes);
  visit(Key::grade_by, d.elements.grade.by);
  visit(Key::grade_smallest, d.elements.grade.smallest);
  visit(Key::grade_width, d.elements.grade.width);
  visit(Key::grade_point, d.elements.grade.point);
  visit(Key::beads_enabled, d.elements.beads.enabled);
  visit(Key::beads_scale, d.elements.beads.scale);
  visit(Key::beads_min_diameter, d.elements.beads.min_diameter);
  visit(Key::beads_over, d.elements.beads.over);
  visit(Key::placement_offset, d.placement.offset);
  visit(Key::rotation_deg, d.placement.rotation_deg);
  visit(Key::placement_scale, d.placement.scale);
  visit(Key::band_rows, d.placement.band_rows);
  visit(Key::cut_axis, d.placement.cut_axis);
  visit(Key::align, d.placement.align);
  visit(Key::fit_offset, d.placement.fit_offset);
#define PAVER_SOLVER_VISIT(type, name, ...) visit(Key::solver_##name, d.solver.name);
  PAVER_SOLVER_PARAMETERS(PAVER_SOLVER_VISIT)
#undef PAVER_SOLVER_VISIT
  visit(Key::edits_moved, d.edits.moved);
  visit(Key::edits_deleted, d.edits.deleted);
  visit(Key::edits_added, d.edits.added);
  visit(Key::guidance, d.guidance);
}

// The types of an array's items whose fields are keys of their own.
template <class T>
concept KeyedItem = std::is_same_v<T, EdgeOperator> || std::is_same_v<T, CellVertex> ||
                    std::is_same_v<T, CellEdgeDesign> || std::is_same_v<T, EdgeElementDesign> ||
                    std::is_same_v<T, MovedParticle> || std::is_same_v<T, DeletedElement> ||
                    std::is_same_v<T, AddedElement> || std::is_same_v<T, GuidanceDab>;

// Calls visit(key, field) for every key of an array's item, in the table's order.
template <class T, class Visit>
  requires KeyedItem<std::remove_const_t<T>>
void visit_item_keys(T& item, Visit&& visit) {
  using Item = std::remove_const_t<T>;
  if constexpr (std::is_same_v<Item, EdgeOperator>) {
    visit(Key::operator_op, item.kind); visit(Key::operator_from, item.from); visit(Key::operator_to, item.to);
    visit(Key::operator_offset, item.offset); visit(Key::operator_virtual, item.is_virtual);
  } else if constexpr (std::is_same_v<Item, CellVertex>) {
    visit(Key::cell_vertex_at, item.at);
  } else if constexpr (std::is_same_v<Item, CellEdgeDesign>) {
    visit(Key::cell_edge_from, item.from); visit(Key::cell_edge_to, item.to);
    visit(Key::cell_edge_offset, item.offset); visit(Key::cell_edge_virtual, item.is_virtual);
  } else if constexpr (std::is_same_v<Item, EdgeElementDesign>) {
    visit(Key::edge_t, item.t); visit(Key::edge_scale, item.scale); visit(Key::edge_shape, item.shape);
    visit(Key::edge_cell_edges, item.cell_edges);
  } else if constexpr (std::is_same_v<Item, MovedParticle>) {
    visit(Key::moved_id, item.id); visit(Key::moved_uv, item.uv); visit(Key::moved_pinned, item.pinned);
  } else if constexpr (std::is_same_v<Item, DeletedElement>) {
    visit(Key::deleted_id, item.id); visit(Key::deleted_uv, item.uv);
  } else if constexpr (std::is_same_v<Item, AddedElement>) {
    visit(Key::added_id, item.id); visit(Key::added_uv, item.uv);
  } else {
    visit(Key::dab_uv, item.uv); visit(Key::dab_radius, item.radius); visit(Key::dab_strength, item.strength);
  }
}

// Every key's value against its range (numbers, and each number of a pair or list, finite),
// naming the key with its index: "'elements.edge[0].t' must be in [0, 1], got 1.5". Empty when
// all are in range; the first refusal otherwise.
std::optional<std::string> key_range_problem(const Design& design);

// Sets a key that a flag names from the flag's text ("0.1", "tri", "" for a Bool flag: true), as
// `paver run` does: a refusal says what the value must be ("must be finite and >= 0 (surface
// units)"), and `design` is left as it was.
std::optional<std::string> set_key_from_text(Design& design, Key key, std::string_view text);

// The keys `paver run` takes as flags, in the table's order.
std::vector<Key> flag_keys();

// The Markdown table of every key (docs/design_file.md, between its markers).
std::string design_keys_markdown();

}  // namespace paver
