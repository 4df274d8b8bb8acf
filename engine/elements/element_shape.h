#pragma once
// Element shapes (section 4.1): unit-diameter triangle meshes centred at the origin, with +Z the
// surface normal they get aligned to. The widest horizontal extent is 1 so that scaling by the
// element diameter makes the element exactly that wide.
#include "design/shape_kind.h"
#include "mesh/polygon_soup.h"

#include <glm/vec3.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace paver {

struct ShapeMesh {
  std::vector<glm::vec3> positions;   // #V, inside the unit-diameter disc in the XY plane (the contact
                                      // rule's footprint), centred at the origin (a custom shape:
                                      // in XY, and in Z unless the file puts its base elsewhere)
  std::vector<glm::ivec3> triangles;  // #F, counter-clockwise seen from outside
};

// Paver's round brilliant (ShapeKind::Gem) in units of its girdle diameter, written once for the
// shape, the seats cut for it (cut/seat_cutter.h) and its carat weight (report/bill_of_stones.h).
inline constexpr double kGemTableRadius = 0.28;     // table diameter 0.56
inline constexpr double kGemCrownHeight = 0.16;     // girdle top to table
inline constexpr double kGemPavilionDepth = 0.43;   // girdle bottom to culet
inline constexpr double kGemGirdleHalf = 0.01;      // girdle thickness 0.02
inline constexpr double kGemDepth = kGemCrownHeight + 2 * kGemGirdleHalf + kGemPavilionDepth;  // table to culet

// How finely shapes are tessellated: Full for export, Coarse for drawing thousands of elements
// (a sphere of 80 triangles instead of 288), Minimal for more, each a few pixels wide (a sphere is a hexagonal bipyramid of 12 triangles, a gem an octagonal table,
// crown and pavilion of 32). Every detail has the same unit width and footprint.
enum class ShapeDetail { Full, Coarse, Minimal };

// Built-in shapes: Sphere (UV sphere), Gem (round brilliant cut: table, crown, girdle, pavilion;
// table towards +Z), HexPrism (height 0.5), Disc (cylinder of height 0.2). Custom throws.
ShapeMesh make_builtin_shape(ShapeKind kind, ShapeDetail detail = ShapeDetail::Full);

// Loads an OBJ, OFF, PLY or STL file with the surfaces' readers (mesh/read_mesh_file.h) and
// normalises it: centred on its bounding box in XY, scaled so its outline fits the unit disc; in Z
// the file's z = 0 is kept as the surface when it lies within the shape, else it is centred. Throws
// InputError ("custom shape <file>: ...", the place and what is wrong) when it cannot.
ShapeMesh load_custom_shape(const std::filesystem::path& path);
// The same normalisation for a file already read; `source` starts its error messages.
ShapeMesh custom_shape_from_soup(const PolygonSoup& soup, const std::string& source);

// Edges of `shape` with one face only: a closed shape has none. An open custom shape exports as
// open surfaces, which a printer or a boolean cannot take (the pipeline warns).
long open_edge_count(const ShapeMesh& shape);

}  // namespace paver
