#include "script.h"

#include "core/input_error.h"

#include <gtest/gtest.h>

#include <string>

namespace paver::studio {
namespace {

using Kind = ScriptCommand::Kind;

std::string error_of(const std::string& text) {
  try {
    parse_script(text, "s.txt");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Script, ParsesEveryCommand) {
  const auto commands = parse_script(
      "open assets/surfaces/dome.obj\n"
      "cut_axis x\n"
      "design assets/designs/dome_hex_d6.json\n"
      "pattern hex\n"
      "spacing 6\n"
      "set solver.dt 0.25\n"
      "optimize\nundo\nredo\n"
      "export out/dir\n"
      "screenshot shot.png\n"
      "view3d\nview2d\n"
      "wait 3\n"
      "quit\n",
      "s.txt");
  ASSERT_EQ(commands.size(), 15u);
  const Kind kinds[] = {Kind::Open,   Kind::CutAxis, Kind::Design, Kind::Pattern, Kind::Spacing,    Kind::Set,    Kind::Optimize,
                        Kind::Undo,   Kind::Redo,   Kind::Export,  Kind::Screenshot, Kind::View3d, Kind::View2d,
                        Kind::Wait,   Kind::Quit};
  for (std::size_t i = 0; i < commands.size(); ++i) {
    EXPECT_EQ(commands[i].kind, kinds[i]) << i;
    EXPECT_EQ(commands[i].line, int(i) + 1);
  }
  EXPECT_EQ(commands[0].text, "assets/surfaces/dome.obj");
  EXPECT_EQ(commands[1].text, "x");
  EXPECT_EQ(commands[3].text, "hex");
  EXPECT_EQ(commands[4].number, 6);
  EXPECT_EQ(commands[5].text, "solver.dt");
  EXPECT_EQ(commands[5].value, "0.25");
  EXPECT_EQ(commands[9].text, "out/dir");
  EXPECT_EQ(commands[13].frames, 3);
}

TEST(Script, SkipsCommentsAndBlankLinesButCountsThem) {
  const auto commands = parse_script("# a session\n\n   \nundo   # go back\n\t redo\r\n", "s.txt");
  ASSERT_EQ(commands.size(), 2u);
  EXPECT_EQ(commands[0].kind, Kind::Undo);
  EXPECT_EQ(commands[0].line, 4);
  EXPECT_EQ(commands[1].kind, Kind::Redo);
  EXPECT_EQ(commands[1].line, 5);
}

TEST(Script, PathsKeepBlanksAndHashesInsideWords) {
  const auto commands = parse_script("open my surfaces/dome#2.obj  # the second dome\n", "s.txt");
  ASSERT_EQ(commands.size(), 1u);
  EXPECT_EQ(commands[0].text, "my surfaces/dome#2.obj");
}

TEST(Script, SetKeepsTheWholeValue) {
  const auto commands = parse_script("set placement.offset [1.5, -2]\nset elements.vertex.shape gem\n", "s.txt");
  ASSERT_EQ(commands.size(), 2u);
  EXPECT_EQ(commands[0].text, "placement.offset");
  EXPECT_EQ(commands[0].value, "[1.5, -2]");
  EXPECT_EQ(commands[1].value, "gem");
}

TEST(Script, ErrorsNameTheLineAndTheFix) {
  EXPECT_EQ(error_of("undo\nfrobnicate\n").rfind("s.txt:2: unknown command 'frobnicate'", 0), 0u)
      << error_of("undo\nfrobnicate\n");
  EXPECT_NE(error_of("pattern penrose").find("use tri, grid, hex, cairo, prismatic or cell"), std::string::npos);
  EXPECT_NE(error_of("spacing -1").find("finite number >= 0"), std::string::npos);
  EXPECT_NE(error_of("spacing 6mm").find("finite number >= 0"), std::string::npos);
  EXPECT_NE(error_of("set solver.dt").find("needs a value"), std::string::npos);
  EXPECT_NE(error_of("open").find("needs a file path"), std::string::npos);
  EXPECT_NE(error_of("export").find("needs a folder"), std::string::npos);
  EXPECT_NE(error_of("wait 1.5").find("whole number"), std::string::npos);
  EXPECT_NE(error_of("quit now").find("takes no argument"), std::string::npos);
  EXPECT_NE(error_of("screenshot shot.jpg").find(".png"), std::string::npos);
  EXPECT_NE(error_of("cut_axis w").find("use auto, x, y or z"), std::string::npos);
  EXPECT_EQ(error_of("\n\n  optimize extra").rfind("s.txt:3:", 0), 0u);
}

TEST(Script, ElementCommandsTakeAnIdAndNumbers) {
  const auto commands = parse_script("select 4\npin 12\nunpin 12\ndrag 12 0.4 -0.1\ndelete 7\nadd 1.5 -2\n", "s.txt");
  ASSERT_EQ(commands.size(), 6u);
  const Kind kinds[] = {Kind::Select, Kind::Pin, Kind::Unpin, Kind::Drag, Kind::Delete, Kind::Add};
  for (std::size_t i = 0; i < commands.size(); ++i) EXPECT_EQ(commands[i].kind, kinds[i]) << i;
  EXPECT_EQ(commands[0].id, 4);
  EXPECT_EQ(commands[3].id, 12);
  EXPECT_EQ(commands[3].u, 0.4);
  EXPECT_EQ(commands[3].v, -0.1);
  EXPECT_EQ(commands[4].id, 7);
  EXPECT_EQ(commands[5].u, 1.5);
  EXPECT_EQ(commands[5].v, -2);
  EXPECT_NE(error_of("pin").find("pin needs an element id"), std::string::npos);
  EXPECT_NE(error_of("pin -3").find("whole number >= 0"), std::string::npos);
  EXPECT_NE(error_of("delete 3 4").find("takes one element id"), std::string::npos);
  EXPECT_NE(error_of("drag 3 0.4").find("two numbers of spacings D"), std::string::npos);
  EXPECT_NE(error_of("add 1 nan").find("two numbers U V"), std::string::npos);
  const auto brush = parse_script("brush 1 -2 4 0.3\n", "s.txt");
  ASSERT_EQ(brush.size(), 1u);
  EXPECT_EQ(brush[0].kind, Kind::Brush);
  EXPECT_EQ(brush[0].radius, 4);
  EXPECT_EQ(brush[0].strength, 0.3);
  EXPECT_NE(error_of("brush 1 2 0 0.3").find("radius > 0"), std::string::npos);
  EXPECT_EQ(parse_script("colour type\n", "s.txt")[0].kind, Kind::Colour);
  EXPECT_NE(error_of("colour blue").find("use ratio or type"), std::string::npos);
  EXPECT_NE(error_of("brush 1 2 3 -0.9").find("[-0.5, 1]"), std::string::npos);
}

TEST(Script, ABoxSelectsAndTheSelectionIsPinnedOrDeleted) {
  const auto commands = parse_script("select_box -1 -2 3 4\npin selection\nunpin selection\ndelete selection\n", "s.txt");
  ASSERT_EQ(commands.size(), 4u);
  EXPECT_EQ(commands[0].kind, Kind::SelectBox);
  EXPECT_EQ(commands[0].u, -1);
  EXPECT_EQ(commands[0].v, -2);
  EXPECT_EQ(commands[0].u1, 3);
  EXPECT_EQ(commands[0].v1, 4);
  for (std::size_t i = 1; i < 4; ++i) EXPECT_EQ(commands[i].id, ScriptCommand::kSelection) << i;
  EXPECT_EQ(commands[3].kind, Kind::Delete);
  EXPECT_NE(error_of("select_box 1 2 3").find("four numbers"), std::string::npos);
  EXPECT_EQ(parse_script("browse save\n", "s.txt")[0].kind, Kind::Browse);
  const auto mouse = parse_script("click 1 2\nclick 1 2 ctrl\nmouse_drag 0 0 3 4 shift\nkey Delete\n", "s.txt");
  ASSERT_EQ(mouse.size(), 4u);
  EXPECT_EQ(mouse[0].kind, Kind::Click);
  EXPECT_FALSE(mouse[0].ctrl || mouse[0].shift);
  EXPECT_TRUE(mouse[1].ctrl);
  EXPECT_EQ(mouse[2].kind, Kind::MouseDrag);
  EXPECT_EQ(mouse[2].u1, 3);
  EXPECT_EQ(mouse[2].v1, 4);
  EXPECT_TRUE(mouse[2].shift);
  EXPECT_EQ(mouse[3].kind, Kind::Key);
  EXPECT_NE(error_of("click 1 2 alt").find("then optionally shift or ctrl"), std::string::npos);
  EXPECT_NE(error_of("mouse_drag 1 2 3").find("four numbers"), std::string::npos);
  EXPECT_NE(error_of("key F13").find("use E, P"), std::string::npos);
  const auto drag3d = parse_script("mouse_drag3d 42 0.5 -1\n", "s.txt");
  ASSERT_EQ(drag3d.size(), 1u);
  EXPECT_EQ(drag3d[0].kind, Kind::MouseDrag3d);
  EXPECT_EQ(drag3d[0].id, 42);
  EXPECT_EQ(drag3d[0].v, -1);
  EXPECT_NE(error_of("mouse_drag3d 42 0.5").find("an element id and a map point"), std::string::npos);
  EXPECT_NE(error_of("browse everything").find("use surface, design, save, export or shape"), std::string::npos);
  EXPECT_NE(error_of("drag selection 1 0").find("whole number >= 0"), std::string::npos) << "a drag takes one element";
  EXPECT_NE(error_of("select selection").find("whole number >= 0"), std::string::npos);
}

TEST(Script, TypeNamesAFieldTheTextAndHowItIsLetGo) {
  const auto typed = parse_script("type \"stone diameter\" 0\ntype \"D (spacing)\" 0-5 away\ntype gap \"\" tab\n", "s.txt");
  ASSERT_EQ(typed.size(), 3u);
  EXPECT_EQ(typed[0].kind, Kind::Type);
  EXPECT_EQ(typed[0].text, "stone diameter");
  EXPECT_EQ(typed[0].value, "0");
  EXPECT_EQ(typed[0].type_end, TypeEnd::Enter) << "Enter unless told";
  EXPECT_EQ(typed[1].text, "D (spacing)");
  EXPECT_EQ(typed[1].value, "0-5");
  EXPECT_EQ(typed[1].type_end, TypeEnd::Away);
  EXPECT_EQ(typed[2].text, "gap");
  EXPECT_EQ(typed[2].value, "") << "a quoted empty text clears the field";
  EXPECT_EQ(typed[2].type_end, TypeEnd::Tab);
  EXPECT_NE(error_of("type \"stone diameter 0").find("a quote is not closed"), std::string::npos);
  EXPECT_NE(error_of("type gap").find("the text to type"), std::string::npos);
  EXPECT_NE(error_of("type gap 1 escape").find("end with enter, tab or away"), std::string::npos);
}

TEST(Script, OrbitTakesDegreesAndFrames) {
  const auto orbit = parse_script("orbit -45.5 30\n", "s.txt");
  ASSERT_EQ(orbit.size(), 1u);
  EXPECT_EQ(orbit[0].kind, Kind::Orbit);
  EXPECT_EQ(orbit[0].number, -45.5);
  EXPECT_EQ(orbit[0].frames, 30);
  for (const char* bad : {"orbit 90", "orbit ninety 10", "orbit 90 0", "orbit 90 2.5", "orbit inf 10"})
    EXPECT_NE(error_of(bad).find("give degrees and a whole number of frames >= 1"), std::string::npos) << bad;
}

TEST(Script, MissingFileIsAnInputError) {
  EXPECT_THROW(load_script("/nonexistent/session.txt"), InputError);
}

}  // namespace
}  // namespace paver::studio

namespace paver::studio {
namespace {

TEST(Script, PanelNamesASidePanel) {
  for (std::string_view name : kPanelNames) {
    const auto commands = parse_script("panel " + std::string(name), "s.txt");
    ASSERT_EQ(commands.size(), 1u);
    EXPECT_EQ(commands[0].kind, ScriptCommand::Kind::Panel);
    EXPECT_EQ(commands[0].text, name);
  }
  EXPECT_NE(error_of("panel solver\n").find("s.txt:1: panel 'solver': use file, pattern, elements, optimize"),
            std::string::npos);
  EXPECT_NE(error_of("panel\n").find("panel needs a panel name"), std::string::npos);
}

}  // namespace
}  // namespace paver::studio
