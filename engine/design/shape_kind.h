#pragma once
// Which shape an element has (section 4.1): the design's word for it; the meshes themselves are
// made in elements/element_shape.h.
#include "core/enum_names.h"

namespace paver {

enum class ShapeKind { Sphere, Gem, HexPrism, Disc, Custom };

PAVER_ENUM_NAMES(ShapeKind, {ShapeKind::Sphere, "sphere"}, {ShapeKind::Gem, "gem"}, {ShapeKind::HexPrism, "hex_prism"},
                 {ShapeKind::Disc, "disc"}, {ShapeKind::Custom, "custom"});

}  // namespace paver
