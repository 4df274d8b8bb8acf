// The file panel: open a surface (path box, recent files; or drop a file on the window), load and
// save the design, export the outputs, and undo / redo.
#include "panels.h"

#include "../studio.h"

#include "io/element_export.h"
#include "elements/element_proximity.h"
#include "core/input_error.h"
#include "report/pavement_quality.h"

#include <imgui_stdlib.h>

#include <algorithm>
#include <filesystem>
#include <initializer_list>
#include <functional>
#include <string>

namespace paver::studio {
namespace {

namespace fs = std::filesystem;

// Runs a file action; its errors go to the error dialog, never further.
void guarded(Document& doc, const std::function<void()>& action) {
  try {
    action();
  } catch (const std::exception& e) {
    report_error(doc, e);
  }
}

// One of the element files alone, into the export folder.
void export_one(Studio& s, const char* name,
                const std::function<void(const fs::path&, const Elements&, const ElementMeshOptions&)>& write) {
  guarded(s.doc, [&] {
    if (!result_is_final(s)) throw InputError("nothing to export yet: the pavement for this design is not finished");
    const fs::path path = fs::path(s.ui.export_dir) / name;
    prepare_output(s.doc, path);
    // The same colours as "Export all" and `paver run`: nearest-neighbour ratio.
    const Elements& elements = s.doc.result.pavement->elements;
    const auto colours = contact_colours(elements, s.doc.result.pavement->design.elements.gap);
    write(path, elements, {.custom = custom_shape(s.doc), .colours = &colours});
    report_status(s.doc, "wrote " + path.string());
  });
}

// A path field as wide as the panel leaves beside the buttons that follow it on its line.
void path_field(const char* id, std::string& path, std::initializer_list<const char*> buttons) {
  const ImGuiStyle& style = ImGui::GetStyle();
  float room = 0;
  for (const char* b : buttons)
    room += ImGui::CalcTextSize(b, nullptr, true).x + 2 * style.FramePadding.x + style.ItemSpacing.x;
  ImGui::SetNextItemWidth(std::max(ImGui::GetFontSize() * 6, ImGui::GetContentRegionAvail().x - room));
  ImGui::InputText(id, &path);
}

}  // namespace

void file_panel(Studio& s) {
  Document& doc = s.doc;
  section("Surface");
  path_field("##surface", s.ui.surface_path, {"Open", "Browse..."});
  ImGui::SameLine();
  if (ImGui::Button("Open") && !s.ui.surface_path.empty()) open_surface(s, s.ui.surface_path);
  ImGui::SameLine();
  if (ImGui::Button("Browse...##surface")) start_browsing(s.ui.browser, BrowsePurpose::OpenSurface, browse_start(s, BrowsePurpose::OpenSurface));
  if (s.loader.busy()) ImGui::ProgressBar(s.loader.progress(), ImVec2(-1, 0), s.loader.stage().c_str());
  if (doc.surface.map) {
    // A closed surface is counted as loaded, not as its atlas (split faces, seams twice).
    const SurfaceMap& map = *doc.surface.map;
    const bool closed = is_atlas(map);
    ImGui::TextDisabled("%s: %d vertices, %d faces%s", doc.surface.path.filename().string().c_str(),
                        closed ? map.closed_surface_vertices : map.mesh.vertex_count(),
                        closed ? map.closed_surface_faces : map.mesh.face_count(),
                        closed ? (", closed: " + std::to_string(chart_count(map)) + " charts").c_str() : "");
  }
  ImGui::TextDisabled("or drop a surface or a design .json on the window");
  if (doc.surface.map && is_atlas(*doc.surface.map)) {
    CutAxis axis = s.doc.design.placement.cut_axis;
    if (enum_combo("cut across", axis, {"its longest axis", "x", "y", "z"})) set_cut_axis(s, axis);
    help_marker("A closed surface (a bead, a figurine) is paved as charts cut apart by a plane through its "
                "centre, across this axis; stones are added across the seam where both sides leave room. "
                "Changing it maps the surface again.");
  }
  if (!s.recent.empty() && ImGui::TreeNode("recent files")) {
    for (const fs::path& path : std::vector<fs::path>(s.recent))  // opening reorders the list
      if (ImGui::Selectable(path.string().c_str())) open_any(s, path);
    ImGui::TreePop();
  }

  section("Design");
  if (s.ui.design_path.empty()) s.ui.design_path = doc.design_path.string();
  path_field("##design", s.ui.design_path, {"Load", "Save"});
  ImGui::SameLine();
  if (ImGui::Button("Load") && !s.ui.design_path.empty()) open_any(s, s.ui.design_path);
  ImGui::SameLine();
  if (ImGui::Button("Save") && !s.ui.design_path.empty()) save_design_file(doc, s.ui.design_path);
  if (ImGui::Button("Load...")) start_browsing(s.ui.browser, BrowsePurpose::LoadDesign, browse_start(s, BrowsePurpose::LoadDesign));
  ImGui::SameLine();
  if (ImGui::Button("Save as...")) start_browsing(s.ui.browser, BrowsePurpose::SaveDesign, browse_start(s, BrowsePurpose::SaveDesign));
  help_marker("Save as never replaces a design bundled with Paver, nor the surface or shape the design "
              "uses, and asks before it replaces any file but the design's own.");
  ImGui::SameLine();
  ImGui::TextDisabled("%s", doc.dirty ? "unsaved changes" : "saved");
  ImGui::BeginDisabled(!doc.history.can_undo());
  if (ImGui::Button("Undo")) undo(doc);
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(!doc.history.can_redo());
  if (ImGui::Button("Redo")) redo(doc);
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::TextDisabled("%zu / %zu steps", doc.history.undo_count(), doc.history.redo_count());

  section("Export");
  path_field("##export", s.ui.export_dir, {"Browse..."});
  ImGui::SameLine();
  if (ImGui::Button("Browse...##export")) start_browsing(s.ui.browser, BrowsePurpose::ExportFolder, browse_start(s, BrowsePurpose::ExportFolder));
  ImGui::BeginDisabled(!result_is_final(s));
  if (ImGui::Button("Export all")) guarded(doc, [&] { export_outputs(s, s.ui.export_dir); });
  help_marker("placements.csv, stones.csv, elements.ply/.obj/.stl/.glb, paved.3mf, design.json, report.json "
              "and report.html, as `paver run` writes them.");
  if (ImGui::Button("placements.csv"))
    export_one(s, "placements.csv", [](const fs::path& p, const Elements& e, const ElementMeshOptions&) {
      write_placements_csv(p, e);
    });
  ImGui::SameLine();
  if (ImGui::Button("PLY")) export_one(s, "elements.ply", write_elements_ply);
  ImGui::SameLine();
  if (ImGui::Button("OBJ")) export_one(s, "elements.obj", write_elements_obj);
  ImGui::SameLine();
  if (ImGui::Button("STL")) export_one(s, "elements.stl", write_elements_stl);
  ImGui::EndDisabled();
  CutRequest& cut = s.ui.cut;
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 6);
  ImGui::InputDouble("metal thickness", &cut.thickness, 0, 0, "%.3g");
  remember_field_place("metal thickness");
  ImGui::SameLine();
  ImGui::BeginDisabled(!result_is_final(s) || s.cutter.busy() || !MetalCutter::available());
  if (ImGui::Button(s.cutter.busy() ? "cutting..." : "Cut metal"))
    guarded(doc, [&] { cut_metal(s, s.ui.export_dir, cut.thickness); });
  ImGui::EndDisabled();
  help_marker(MetalCutter::available()
                  ? "The surface thickened into metal this thick (surface units, against the normals) with a seat "
                    "cut for each stone and the beads joined: cut.stl and cut.3mf, and the stones alone in stones.3mf, in the "
                    "folder above, as `paver "
                    "run --subtract` writes them. It runs in the background."
                  : "This studio was built without CGAL (-DPAVER_WITH_CGAL=OFF): no cut.");
  if (ImGui::TreeNodeEx("seats, ring size and rules", ImGuiTreeNodeFlags_DefaultOpen)) {
    const auto cut_field = [](const char* label, double& value, const char* help) {
      ImGui::SetNextItemWidth(ImGui::GetFontSize() * 6);
      ImGui::InputDouble(label, &value, 0, 0, "%.3g");
      remember_field_place(label);
      help_marker(help);
    };
    cut_field("seat depth", cut.seat_depth,
              "How far below the surface the stones are set (their girdles, surface units; 0: at the surface): the "
              "seats are cut that deep and stones.3mf holds them there (--seat-depth).");
    cut_field("inside diameter mm", cut.inside_diameter_mm,
              "A band's ring size: the metal's finger side a cylinder this wide, the thickness then its least "
              "(--inside-diameter; 0: the metal follows the normals).");
    cut_field("culet clearance", cut.culet_clearance,
              "A rule: at least this much metal under every culet (surface units; 0: no rule). A stone that breaks "
              "a rule is named and the cut says NOT OK (--culet-clearance).");
    cut_field("seat wall", cut.seat_wall, "A rule: at least this much metal between two seats (--seat-wall; 0: no rule).");
    cut_field("table height", cut.table_height,
              "A rule: no table more than this above the metal (--table-height; 0: no rule).");
    ImGui::TreePop();
  }
  path_field("##png", s.ui.png_path, {"3D view PNG"});
  ImGui::SameLine();
  if (ImGui::Button("3D view PNG")) guarded(doc, [&] { save_view_png(s, s.ui.png_path); });
}

}  // namespace paver::studio
