#pragma once
// How the two views look: the 3D orbit camera, the 2D map view, what is drawn and how elements
// are coloured, and which view is the large one.
#include "renderer.h"

namespace paver::studio {

struct ViewSettings {
  render::OrbitCamera camera;
  render::MapView map_view;
  render::SceneStyle style;
  render::ColourMode colour_mode = render::ColourMode::NeighbourRatio;
  bool large_3d = true;      // the 3D view fills the main area, the 2D view is the inset (or the reverse)
  bool show_legend = true;   // the ratio colours' legend over the 3D view
  double map_aspect = 1.6;   // width / height of the views' area, last drawn: the 2D view frames the whole map in it
};

}  // namespace paver::studio
