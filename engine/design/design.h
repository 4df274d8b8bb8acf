#pragma once
// The whole design of a pavement: pattern, operators, elements, placement and the solver
// parameters of section 5. The CLI and the editor share it; design.json is its file form.
#include "elements/element_shape.h"
#include "pattern/placement.h"
#include "pattern/unit_cell.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace paver {

struct PatternDesign {
  Tessellation tessellation = Tessellation::Hexagon;
  double spacing = 0;                     // D in surface units; 0 = derive from the surface
  std::vector<EdgeOperator> operators;    // applied in order to the unit cell
  bool bracing = true;                    // add virtual edges across non-triangular faces
};

struct VertexElementDesign {
  bool enabled = true;
  double scale = 1;                       // s in (0, 1]: diameter = s * D
  ShapeKind shape = ShapeKind::Sphere;
};

struct EdgeElementDesign {
  double t = 0.5;                         // position along the edge in [0, 1]
  double scale = 0.5;                     // s in (0, 1]: diameter = s * D
  ShapeKind shape = ShapeKind::Sphere;
  std::vector<int> cell_edges;            // unit-cell edge indices it sits on; empty = all
};

struct ElementsDesign {
  VertexElementDesign vertex;
  std::vector<EdgeElementDesign> edge;
  std::string custom_shape;               // OBJ/OFF/PLY/STL path for ShapeKind::Custom
  bool allow_overlap = false;             // allow elements that intersect by design (paper Fig. 15)
};

// Which l_ab the adaptive filter's clamp [l_ab, filter_max * l_ab] uses (NOTES.md: ambiguous).
enum class FilterBase {
  Current,  // recomputed every iteration from the current distortion
  Initial,  // fixed at initialisation
};

std::string_view filter_base_name(FilterBase b);  // "current", "initial"
std::optional<FilterBase> filter_base_from_name(std::string_view name);

// Section 5 parameters. c, m, alpha, beta, gamma, the lambdas, the mu's and filter_max are the
// paper's defaults; dt, threshold, filter_base and stray_patience are our measured choices where
// the paper is silent or ambiguous (docs/solver.md).
struct SolverParams {
  double c = 0;                 // uniform margin, fraction of D_ab (eq. 5); c + m >= 0
  double m = 0;                 // curvature-adaptive margin, fraction of D_ab (eq. 5)
  double alpha = 10;            // k_c(r) = alpha / r^12 - beta / r^6 + gamma (eq. 8)
  double beta = 5;
  double gamma = 1;
  double lambda_r = 0.94;       // restoring force weight (eq. 13)
  double lambda_l = 0.04;       // local-centric force weight
  double lambda_g = 0.02;       // global gravity weight (0.001 for curvature-aware designs)
  double dt = 0.3;              // step size (eq. 14); the paper uses 0.01 to 0.6, 0.5 on flat
                                // surfaces; 0.3 is the largest that measured stable here (docs/solver.md)
  int iterations = 200;         // iteration limit
  double threshold = 1e-3;      // stop when every settled particle moves less than threshold * D
  double mu_compressed = 1;     // filter learning rate for compressed springs (eq. 16)
  double mu_stretched = 0.5;    // filter learning rate for stretched springs
  double filter_max = 1.5;      // clamp l^{t+1} to [l_ab, filter_max * l_ab]
  FilterBase filter_base = FilterBase::Current;  // see docs/solver.md for the measured choice
  int stray_patience = 10;      // a particle pulled back this many iterations in a row is retired (0 = never)
};

struct Design {
  static constexpr int kVersion = 1;
  PatternDesign pattern;
  ElementsDesign elements;
  Placement placement;
  SolverParams solver;
};

// Throws InputError naming the key when a value is out of range.
void validate_design(const Design& design, const std::string& source);

// Whether an element that is placed uses ShapeKind::Custom (so elements.custom_shape is needed).
bool uses_custom_shape(const ElementsDesign& elements);

}  // namespace paver
