#pragma once
// The studio's panels: free functions that draw the parts they are given, every frame, and
// change the design only through change_design (so each change is undoable and re-runs).
#include <imgui.h>

namespace paver::studio {

struct Document;
struct Studio;
struct UiState;

void side_panels(Studio& s, ImVec2 pos, ImVec2 size);  // the tabbed column of the panels below
void pattern_panel(Document& doc, UiState& ui);        // tessellation, D, operators, unit-cell editor
void elements_panel(Document& doc, UiState& ui);       // V- and E-elements, custom shape
void single_elements_panel(Studio& s);                 // the selected stone, pin / delete / move, the edits
void optimization_panel(Studio& s);                    // solver parameters, backend, run control
void report_panel(const Studio& s);                    // quality figures, iterations, timings, histogram
void file_panel(Studio& s);                            // open, recent, design, export, undo/redo
void help_panel();                                     // shortcuts

void views_area(Studio& s, ImVec2 pos, ImVec2 size);   // the 3D and 2D views with their controls
void status_bar(Studio& s, ImVec2 pos, ImVec2 size);
void dialogs(Studio& s);                               // the error dialog, quit with unsaved changes
void file_dialog(Studio& s);                           // the file browser, and Save as's replace question

// A "(?)" after the last item, with `text` as its tooltip.
void help_marker(const char* text);
// A number field that applies when it lets go (Enter, Tab, a click elsewhere), never on every
// keystroke (typing 0.5 must not pave at 0 first); true when the value changed.
bool typed_number(const char* label, double& value, const char* format = "%.4g");
// A separator with a title under it.
void section(const char* title);

}  // namespace paver::studio
