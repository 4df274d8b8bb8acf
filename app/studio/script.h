#pragma once
// The studio's scripted session (--script FILE): one command per line, `#` starts a comment.
//   open PATH | cut_axis auto|x|y|z | design PATH | pattern tri|grid|hex|cairo|prismatic|cell | spacing D | set KEY VALUE | optimize |
//   undo | redo | save FILE.json | export DIR | cut THICKNESS DIR | screenshot FILE.png | view3d | view2d | panel NAME | wait N | quit |
//   select ID | select_box U0 V0 U1 V1 | pin ID|selection | unpin ID|selection | drag ID DU DV |
//   delete ID|selection | add U V | brush U V RADIUS STRENGTH |
//   colour ratio|type | browse surface|design|save|export|shape |
//   click U V [shift|ctrl] | mouse_drag U0 V0 U1 V1 [shift|ctrl] | key E|P|B|I|M|V|L|C|R|N|Delete|Escape|Space |
//   mouse_drag3d ID U V | orbit DEGREES FRAMES | type FIELD TEXT [enter|tab|away]
// (element commands name elements by the ids placements.csv lists; drag moves by DU, DV spacings D
// in the map, add puts a vertex element at map coordinates U, V, placements.csv's u and v; brush
// paints a guidance dab there, RADIUS in spacings D, STRENGTH in [-0.5, 1]: > 0 looser, < 0 denser)
// (click and mouse_drag play the mouse into the large 2D view at map points, mouse_drag3d drags
// element ID in the large 3D view to the surface point at map point U V, key presses a key:
// the views' own mouse handling and the shortcuts run on them, as on a designer's hand)
// (type clicks into the number field labelled FIELD, "quoted" when it has blanks, types TEXT a
// character a frame and lets go with Enter (the default), Tab or a click elsewhere: as a hand does,
// so that what the field does with it, taken or refused, is what a designer meets)
// (orbit turns the 3D camera about its target by DEGREES over FRAMES frames, as a drag does, and
// prints the frames' pace: "frames_while_orbiting ...")
// (browse opens the file dialog for that button, as a click on it does: for screenshots)
// (panel shows a side panel: file, pattern, elements, optimize, report or help; cut_axis picks the
// plane a closed surface is cut across, and opens an open closed surface again with it)
// Parsing is separate from running so that a typo fails before anything is done.
#include "synthetic_input.h"

#include <string>
#include <string_view>
#include <vector>

namespace paver::studio {

struct ScriptCommand {
  enum class Kind { Open, CutAxis, Design, Pattern, Spacing, Set, Optimize, Undo, Redo, Export, Cut, Screenshot, View3d,
                    View2d, Panel, Wait, Quit, Select, Pin, Unpin, Drag, Delete, Add, Brush, Colour, Save, SelectBox, Browse,
                    Click, MouseDrag, Key, MouseDrag3d, Orbit, Type };
  Kind kind = Kind::Quit;
  std::string text;    // open/design/save/export/cut/screenshot: the path; pattern, panel, cut_axis, colour: the name; set: the key
  std::string value;   // set: the value as written
  double number = 0;   // spacing: D; cut: the metal's thickness; orbit: degrees
  int frames = 0;      // wait, orbit: N
  int id = -1;         // select, pin, unpin, drag, delete: the element (kSelection: the selection)
  double u = 0, v = 0; // drag: the move in spacings D; add, brush: the map point
  double radius = 0, strength = 0;  // brush
  double u1 = 0, v1 = 0;             // select_box, mouse_drag: the other corner / end (u, v the first)
  bool shift = false, ctrl = false;  // click, mouse_drag: the modifier held
  int key = -1;                      // key: the GLFW key
  TypeEnd type_end = TypeEnd::Enter;  // type: how the field is let go (text: the field, value: what is typed)
  static constexpr int kSelection = -2;  // pin/unpin/delete `selection`: every selected element
  int line = 0;        // 1-based line in the script, for messages
};

std::string_view command_name(ScriptCommand::Kind kind);

// The side panels, in tab order ("file", "pattern", ...), as `panel NAME` names them.
inline constexpr std::string_view kPanelNames[] = {"file", "pattern", "elements", "optimize", "report", "help"};

// Parses one line into `out`; false for a blank or comment line. Throws InputError
// "SOURCE:LINE: ..." naming the fix.
bool parse_script_line(std::string_view line, int line_number, const std::string& source, ScriptCommand& out);

// Every command of a script's text, in order.
std::vector<ScriptCommand> parse_script(std::string_view text, const std::string& source);

// Reads and parses a script file; throws InputError naming the file when it cannot be read.
std::vector<ScriptCommand> load_script(const std::string& path);

}  // namespace paver::studio
