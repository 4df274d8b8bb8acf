// paver-studio end to end: a scripted session under Xvfb opens the dome, edits the design, undoes
// and redoes, exports and takes a screenshot; the export must be what `paver run` writes for the
// exported design, and the screenshot must show the shaded surface and the coloured elements.
#include "scene.h"

#include <gtest/gtest.h>

#include <cctype>

#include <nlohmann/json.hpp>
#include <stb_image.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <cmath>
#include <iterator>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return std::move(text).str();
}

std::string quote(const std::string& arg) {
  std::string quoted = "'";
  for (char c : arg) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

struct Outcome {
  int exit_code = -1;
  std::string out, err, command;
};

// Runs a shell command from the source folder with stdout and stderr captured in `scratch`.
Outcome run_in_source(const std::string& command, const fs::path& scratch) {
  Outcome r;
  r.command = "cd " + quote(PAVER_SOURCE_DIR) + " && " + command;
  const std::string full = r.command + " >" + quote((scratch / "stdout").string()) + " 2>" +
                           quote((scratch / "stderr").string());
  const int status = std::system(full.c_str());
  if (status != -1 && WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
  r.out = read_text(scratch / "stdout");
  r.err = read_text(scratch / "stderr");
  return r;
}

std::string describe(const Outcome& r) {
  return "command: " + r.command + "\nexit code: " + std::to_string(r.exit_code) + "\n--- stdout ---\n" + r.out +
         "--- stderr ---\n" + r.err;
}

// The studio under a virtual X server, its config (recent files) kept in the scratch folder.
// xvfb-run itself fails now and then (two runs picking one display number, or its clean-up
// racing the server's exit: "xvfb-run: error: ..."); that is retried, never a studio failure.
Outcome studio(const std::string& args, const fs::path& scratch) {
  Outcome r;
  for (int attempt = 0; attempt < 3; ++attempt) {
    r = run_in_source("XDG_CONFIG_HOME=" + quote((scratch / "config").string()) +
                          " xvfb-run -a -s '-screen 0 1280x800x24' " + quote(PAVER_STUDIO) + " " + args,
                      scratch);
    if (r.err.find("xvfb-run: error:") == std::string::npos) break;
  }
  return r;
}

class StudioSession : public testing::Test {
protected:
  void SetUp() override {
    const auto* info = testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("paver_studio_" + std::string(info->name()) + "_" + std::to_string(getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    if (std::system("command -v xvfb-run >/dev/null 2>&1") != 0)
      GTEST_SKIP() << "SKIPPED LOUDLY: xvfb-run is not installed (Debian: xvfb); the studio needs a display";
    const Outcome devices = run_in_source(quote(PAVER_CLI) + " devices", dir_);
    if (devices.exit_code != 0)
      GTEST_SKIP() << "SKIPPED LOUDLY: no Vulkan device (`paver devices` says: " << devices.out << devices.err << ")";
  }
  void TearDown() override {
    std::error_code ignored;
    fs::remove_all(dir_, ignored);
  }
  // A scripted session in a 1280x800 window on the CPU solver.
  Outcome run_script(const fs::path& script) const {
    return studio("--script " + quote(script.string()) + " --backend cpu --width 1280 --height 800", dir_);
  }
  // `paver run ARGS` on the CPU into dir_/cli lays placements.csv byte for byte as the studio
  // exported it into `exported`.
  void expect_the_cli_lays_what_was_exported(const std::string& args, const fs::path& exported) const {
    const fs::path cli_out = dir_ / "cli";
    const Outcome cli =
        run_in_source(quote(PAVER_CLI) + " run " + args + " --backend cpu --formats ply --out " + quote(cli_out.string()), dir_);
    ASSERT_EQ(cli.exit_code, 0) << describe(cli);
    EXPECT_TRUE(read_text(exported / "placements.csv") == read_text(cli_out / "placements.csv"))
        << "placements.csv differs from paver run " << args << "'s";
  }
  // The pendant paved by `paver run` with the studio's starting design as a lattice, into
  // dir_/base: the element ids a session's edits name.
  void pave_lattice_pendant() const {
    const fs::path design = dir_ / "start.json", base = dir_ / "base";
    std::ofstream(design) << R"({"version": 1, "pattern": {"topology": "lattice"}})";
    const Outcome first = run_in_source(quote(PAVER_CLI) + " run assets/surfaces/pendant.obj --design " +
                                            quote(design.string()) + " --backend cpu --out " + quote(base.string()),
                                        dir_);
    ASSERT_EQ(first.exit_code, 0) << describe(first);
  }
  fs::path dir_;
};

TEST_F(StudioSession, ScriptedEditExportsWhatTheCliWritesAndScreenshotShowsThePavement) {
  const fs::path exported = dir_ / "export", shot = dir_ / "shot.png", script = dir_ / "session.txt";
  std::ofstream(script) << "# the brief's session\n"
                           "open assets/surfaces/dome.obj\n"
                           "design assets/designs/dome_hex_d6.json\n"
                           "pattern hex\n"
                           "spacing 6\n"
                           "set solver.dt 0.25\n"
                           "optimize\n"
                           "undo\n"
                           "redo\n"
                           "export " << exported.string() << "\n"
                        << "screenshot " << shot.string() << "\n"
                        << "quit\n";
  const Outcome r = run_script(script);
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  EXPECT_NE(r.out.find("latency_ms "), std::string::npos) << describe(r);

  // Redo brought dt 0.25 back, and the export carries it.
  for (const char* name : {"placements.csv", "stones.csv", "elements.ply", "elements.obj", "elements.stl",
                           "elements.glb", "paved.3mf", "design.json", "report.json", "report.html", "preview.png",
                           "param.png"})
    EXPECT_TRUE(fs::is_regular_file(exported / name)) << name;
  // Export all draws both pictures, as `paver run --png` does, and report.html embeds the preview
  // rather than telling the user to run the CLI with --png.
  for (const char* name : {"preview.png", "param.png"})
    EXPECT_GT(fs::file_size(exported / name), 10000u) << name << " is not a picture of the pavement";
  const std::string html = read_text(exported / "report.html");
  EXPECT_NE(html.find("data:image/png;base64,"), std::string::npos);
  EXPECT_EQ(html.find("run with --png"), std::string::npos);
  const nlohmann::json design = nlohmann::json::parse(read_text(exported / "design.json"));
  EXPECT_EQ(design["solver"]["dt"].get<double>(), 0.25);
  EXPECT_EQ(design["pattern"]["tessellation"], "hex");
  EXPECT_EQ(design["pattern"]["spacing"].get<double>(), 6.0);

  // The CLI on the exported design writes the same files, byte for byte (but the report, whose
  // timings differ): both run the one pipeline and its export stage.
  const fs::path cli_out = dir_ / "cli";
  const Outcome cli = run_in_source(quote(PAVER_CLI) + " run assets/surfaces/dome.obj --design " +
                                    quote((exported / "design.json").string()) + " --backend cpu --out " +
                                    quote(cli_out.string()),
                                dir_);
  ASSERT_EQ(cli.exit_code, 0) << describe(cli);
  const std::string studio_csv = read_text(exported / "placements.csv");
  EXPECT_GT(studio_csv.size(), 1000u);
  EXPECT_TRUE(studio_csv == read_text(cli_out / "placements.csv")) << "placements.csv differs from paver run's";
  for (const char* name : {"elements.ply", "elements.obj", "design.json"})
    EXPECT_TRUE(read_text(exported / name) == read_text(cli_out / name)) << name << " differs from paver run's";
  const nlohmann::json studio_report = nlohmann::json::parse(read_text(exported / "report.json"));
  const nlohmann::json cli_report = nlohmann::json::parse(read_text(cli_out / "report.json"));
  for (const char* section : {"pattern", "elements", "quality_after", "postprocess", "collision_resolution"}) {
    nlohmann::json a = studio_report[section], b = cli_report[section];
    a.erase("milliseconds"), b.erase("milliseconds");
    // The studio's run chose the topology (auto); design.json carries the choice, so the CLI's
    // run of it has nothing to choose.
    a.erase("topology_choice"), b.erase("topology_choice");
    EXPECT_EQ(a, b) << "report.json's " << section << " differs";
  }

  // The screenshot: the whole window, not blank, with the grey surface and the green (loose to
  // touching) elements of the ratio colour scale.
  int width = 0, height = 0, channels = 0;
  unsigned char* pixels = stbi_load(shot.string().c_str(), &width, &height, &channels, 3);
  ASSERT_NE(pixels, nullptr) << "cannot read " << shot;
  EXPECT_EQ(width, 1280);
  EXPECT_EQ(height, 800);
  std::set<int> colours;
  long grey = 0, green = 0;
  for (long i = 0; i < long(width) * height; ++i) {
    const int r = pixels[3 * i], g = pixels[3 * i + 1], b = pixels[3 * i + 2];
    colours.insert(r << 16 | g << 8 | b);
    if (std::abs(r - g) < 12 && std::abs(g - b) < 12 && r > 90 && r < 245) ++grey;
    if (g > r + 30 && g > b + 10) ++green;
  }
  stbi_image_free(pixels);
  EXPECT_GT(colours.size(), 1000u) << "a blank or flat screenshot";
  EXPECT_GT(grey, 20000) << "the surface's grey shading is missing";
  EXPECT_GT(green, 5000) << "the elements' ratio colours are missing";

  // The surface went into the recent files, kept in the config folder.
  EXPECT_NE(read_text(dir_ / "config/paver/recent.txt").find("dome.obj"), std::string::npos);
}

// Pixels in a 1280x800 screenshot's views (right of the side panels, below the toolbar, whose
// checkboxes are blue too) whose blue exceeds their red and green by the margins given; -1 when
// the file cannot be read.
long blue_view_pixels(const fs::path& shot, int over_red, int over_green) {
  int width = 0, height = 0, channels = 0;
  unsigned char* pixels = stbi_load(shot.string().c_str(), &width, &height, &channels, 3);
  if (!pixels) return -1;
  long blue = 0;
  for (int y = 60; y < height - 40; ++y)
    for (int x = 440; x < width; ++x) {
      const unsigned char* p = pixels + 3 * (long(y) * width + x);
      if (p[2] > p[0] + over_red && p[2] > p[1] + over_green) ++blue;
    }
  stbi_image_free(pixels);
  return blue;
}

// The pattern's blue lines (30, 90, 200) and their shades.
long lattice_blue_pixels(const fs::path& shot) { return blue_view_pixels(shot, 90, 50); }

TEST_F(StudioSession, ThePatternsLinesAppearWhenShownAfterTheRun) {
  // A run uploads the pattern's lines only while they are shown (they are most of a live
  // upload's time); showing them afterwards (L) must draw the run's pattern all the same.
  const fs::path hidden = dir_ / "hidden.png", shown = dir_ / "shown.png", script = dir_ / "session.txt";
  // In the 2D map, large, where the lines show between the disks.
  std::ofstream(script) << "open assets/surfaces/pendant.obj\noptimize\nview2d\nwait 2\n"
                        << "screenshot " << hidden.string() << "\nkey L\nwait 2\n"
                        << "screenshot " << shown.string() << "\nquit\n";
  const Outcome r = run_script(script);
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  const long before = lattice_blue_pixels(hidden), after = lattice_blue_pixels(shown);
  ASSERT_GE(before, 0) << "cannot read " << hidden;
  EXPECT_GT(after, before + 250) << "blue line pixels: " << before << " hidden, " << after << " shown";
}

// While a run of 46k stones solves, the views draw each live image a slice per frame and show it
// once complete (a whole image takes lavapipe longer than a frame). The live view must still
// follow the run: images completed during it, and the final pavement drawn when it ends.
TEST_F(StudioSession, TheViewsFollowALargeRunWithImagesDrawnInSlices) {
  const fs::path script = dir_ / "session.txt", final_png = dir_ / "final.png";
  std::ofstream(script) << "open assets/surfaces/pendant.obj\nspacing 0.12\noptimize\n"
                        << "screenshot " << final_png.string() << "\nquit\n";
  const Outcome r = run_script(script);
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  const std::size_t at = r.out.rfind("frames_while_solving ");  // the large run, after the launch's short one
  ASSERT_NE(at, std::string::npos) << describe(r);
  const std::string line = r.out.substr(at, r.out.find('\n', at) - at);
  const std::size_t images_at = line.find("live images ");
  ASSERT_NE(images_at, std::string::npos) << line;
  EXPECT_GE(std::stoi(line.substr(images_at + 12)), 2) << line;
  EXPECT_TRUE(fs::exists(final_png));
}

// Turning the 3D view of 46k stones: on lavapipe a whole image takes 80+ ms, so while the camera
// moves the view shows a quick image of the surface alone, and the full image is drawn in slices
// once it rests. On any device the full image is what the view shows in the end.
TEST_F(StudioSession, TurningAHeavyViewShowsQuickImagesThenTheFullOne) {
  const fs::path script = dir_ / "session.txt";
  std::ofstream(script) << "open assets/surfaces/pendant.obj\nspacing 0.12\noptimize\norbit 40 20\nwait 100\nquit\n";
  const Outcome r = run_script(script);
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  ASSERT_NE(r.out.find("frames_while_orbiting 20,"), std::string::npos) << describe(r);
  const std::size_t at = r.out.find("view 3D: ");
  ASSERT_NE(at, std::string::npos) << describe(r);
  const std::string line = r.out.substr(at, r.out.find('\n', at) - at);
  EXPECT_NE(line.find("showing the full image"), std::string::npos) << line;
  // "last full image X ms, Q quick images": X is the whole image that decided (slices and quick
  // images do not measure the view), so every turned frame is quick exactly when X is over the
  // threshold: on lavapipe with 2 cores 80+ ms, on a GPU a few.
  const double whole_ms = std::stod(line.substr(line.find("last full image ") + 16));
  const int quick = std::stoi(line.substr(line.find(" ms, ") + 5));
  if (whole_ms > paver::studio::kQuickImageAboveMs)
    EXPECT_GE(quick, 20) << "every turned frame drew a quick image: " << line;
  else
    EXPECT_EQ(quick, 0) << "a view quick to draw is drawn whole as it turns: " << line;
}

// The V elements' blue (52, 101, 164) in the colouring by type and its shades: not the ratio
// scale's greens and reds, nor the grey surface.
long type_blue_pixels(const fs::path& shot) { return blue_view_pixels(shot, 60, 30); }

// A run paused mid-way shows its particles; changing the colouring then recolours them although
// no newer snapshot comes: the live frame, prepared off the UI thread, is asked for again. (A
// frame still being prepared in the old colouring when it changes is also asked again; that race
// is too narrow for a session to hit reliably, so it is this test's aim, not its proof.)
TEST_F(StudioSession, APausedRunIsRecolouredWhenTheColouringChanges) {
  const fs::path ratio = dir_ / "ratio.png", typed = dir_ / "typed.png", script = dir_ / "session.txt";
  // The colouring changes right after the pause, while the paused frame may still be prepared.
  std::ofstream(script) << "open assets/surfaces/pendant.obj\nspacing 0.12\nwait 40\n"
                        << "screenshot " << ratio.string() << "\nkey Space\ncolour type\nwait 40\n"
                        << "screenshot " << typed.string() << "\nquit\n";
  const Outcome r = run_script(script);
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  const long before = type_blue_pixels(ratio), after = type_blue_pixels(typed);
  ASSERT_GE(before, 0) << "cannot read " << ratio;
  EXPECT_GT(after, before + 5000) << "blue V-element pixels: " << before << " by ratio, " << after << " by type";
}

// placements.csv as id -> (u, v, x, y, z, diameter).
struct Row {
  double u, v, x, y, z, diameter;
  char kind;
};
std::map<long, Row> placements_by_id(const fs::path& csv) {
  std::map<long, Row> rows;
  std::istringstream in(read_text(csv));
  std::string line;
  std::getline(in, line);  // header: id,kind,x,y,z,nx,ny,nz,diameter,u,v
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::vector<std::string> f;
    for (std::string field; std::getline(fields, field, ',');) f.push_back(field);
    if (f.size() != 11) continue;
    rows[std::stol(f[0])] = {std::stod(f[9]), std::stod(f[10]), std::stod(f[2]), std::stod(f[3]), std::stod(f[4]),
                             std::stod(f[8]), f[1][0]};
  }
  return rows;
}

// A script's start for editing stones with the mouse: the lattice pendant paved, the 2D view large
// without the inset, stone editing on.
constexpr const char* kMouseEditingOnTheLatticePendant =
    "open assets/surfaces/pendant.obj\nset pattern.topology lattice\noptimize\nview2d\nkey I\nkey E\n";

// The vertex element whose map point is nearest (u, v).
long nearest_vertex_element(const std::map<long, Row>& rows, double u, double v) {
  long nearest = -1;
  double best = 1e300;
  for (const auto& [id, row] : rows)
    if (row.kind == 'V' && std::hypot(row.u - u, row.v - v) < best) best = std::hypot(row.u - u, row.v - v), nearest = id;
  return nearest;
}

// The contact rule over all pairs, from the file: pairs closer than the sum of their radii.
long contact_violations(const std::map<long, Row>& rows) {
  long violations = 0;
  for (auto a = rows.begin(); a != rows.end(); ++a)
    for (auto b = std::next(a); b != rows.end(); ++b) {
      const Row &p = a->second, &q = b->second;
      if (std::hypot(p.x - q.x, p.y - q.y, p.z - q.z) < 0.5 * (p.diameter + q.diameter)) ++violations;
    }
  return violations;
}

// The vertex element nearest the map's middle, and one two spacings D from it.
std::pair<long, long> centre_and_two_away(const std::map<long, Row>& rows, double D) {
  long centre_id = -1, other = -1;
  double nearest = 1e300, off = 1e300;
  for (const auto& [id, row] : rows)
    if (row.kind == 'V' && std::hypot(row.u, row.v) < nearest) nearest = std::hypot(row.u, row.v), centre_id = id;
  const Row& centre = rows.at(centre_id);
  for (const auto& [id, row] : rows) {
    const double o = std::abs(std::hypot(row.u - centre.u, row.v - centre.v) - 2 * D);
    if (row.kind == 'V' && o < off) off = o, other = id;
  }
  return {centre_id, other};
}

// The issue's session: open the pendant, pin one element, drag it by 0.4 D, delete another,
// re-optimize and export: the pinned one moved, the deleted one is gone, nothing else is lost,
// no pair violates the contact rule, and `paver run` on the saved design writes the same file.
TEST_F(StudioSession, PinDragAndDeleteSingleElementsAndTheCliReproducesThem) {
  // The studio's starting design, as a lattice: its ids from a CLI run first.
  ASSERT_NO_FATAL_FAILURE(pave_lattice_pendant());
  const fs::path base = dir_ / "base";
  const std::map<long, Row> before = placements_by_id(base / "placements.csv");
  ASSERT_GT(before.size(), 500u);
  const double D = nlohmann::json::parse(read_text(base / "design.json"))["pattern"]["spacing"].get<double>();
  const auto [pinned, deleted] = centre_and_two_away(before, D);
  const Row centre = before.at(pinned);

  const fs::path edited = dir_ / "edited", script = dir_ / "edit.txt";
  std::ofstream(script) << "open assets/surfaces/pendant.obj\n"
                           "set pattern.topology lattice\n"
                           "optimize\n"
                        << "select " << pinned << "\n"
                        << "pin " << pinned << "\n"
                        << "drag " << pinned << " 0.4 0\n"
                        << "delete " << deleted << "\n"
                        << "undo\n"
                        << "redo\n"
                        << "optimize\n"
                        << "export " << edited.string() << "\n";
  const Outcome r = run_script(script);
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  const std::map<long, Row> after = placements_by_id(edited / "placements.csv");
  ASSERT_TRUE(after.count(pinned));
  EXPECT_NEAR(after.at(pinned).u, centre.u + 0.4 * D, 1e-5 * D) << "the dragged element is not where it was put";
  EXPECT_NEAR(after.at(pinned).v, centre.v, 1e-5 * D);
  EXPECT_FALSE(after.count(deleted)) << "the deleted element is still there";
  for (const auto& [id, row] : before) {
    if (id != deleted) {
      EXPECT_TRUE(after.count(id)) << "element " << id << " was lost";
    }
  }
  EXPECT_EQ(after.size() + 1, before.size());
  // The contact rule over all pairs, from the file.
  EXPECT_EQ(contact_violations(after), 0);
  const nlohmann::json saved = nlohmann::json::parse(read_text(edited / "design.json"));
  EXPECT_EQ(saved["edits"]["moved"].size(), 1u);
  EXPECT_EQ(saved["edits"]["deleted"].size(), 1u);

  // The saved design reproduces the edited pavement on the CLI, byte for byte.
  const fs::path cli_out = dir_ / "cli";
  const Outcome cli = run_in_source(quote(PAVER_CLI) + " run assets/surfaces/pendant.obj --design " +
                                        quote((edited / "design.json").string()) + " --backend cpu --out " +
                                        quote(cli_out.string()),
                                    dir_);
  ASSERT_EQ(cli.exit_code, 0) << describe(cli);
  EXPECT_NE(cli.out.find("edits    1 moved (1 pinned), 0 added, 1 deleted"), std::string::npos) << cli.out;
  EXPECT_TRUE(read_text(edited / "placements.csv") == read_text(cli_out / "placements.csv"));
}

// The trial's session on the bundled pendant's gems (tight pavé): pin a stone, drag it 0.25 D,
// delete another. It lost 11 stones (29 in this build before the edits kept the way that loses
// fewer); now at most 3 besides the deleted one, and the dragged stone stays where it was dropped.
TEST_F(StudioSession, EditingTightPaveLosesAtMostThreeStones) {
  const fs::path base = dir_ / "base";
  const Outcome first = run_in_source(quote(PAVER_CLI) +
                                          " run assets/surfaces/pendant.obj --design assets/designs/pendant_tri_gems.json"
                                          " --backend cpu --formats ply --out " + quote(base.string()),
                                      dir_);
  ASSERT_EQ(first.exit_code, 0) << describe(first);
  const std::map<long, Row> before = placements_by_id(base / "placements.csv");
  const double D = nlohmann::json::parse(read_text(base / "design.json"))["pattern"]["spacing"].get<double>();
  const auto [pinned, deleted] = centre_and_two_away(before, D);
  const Row centre = before.at(pinned);
  const fs::path edited = dir_ / "edited", script = dir_ / "edit.txt";
  std::ofstream(script) << "open assets/surfaces/pendant.obj\ndesign assets/designs/pendant_tri_gems.json\noptimize\n"
                        << "select " << pinned << "\npin " << pinned << "\ndrag " << pinned << " 0.25 0\n"
                        << "delete " << deleted << "\noptimize\nexport " << edited.string() << "\nquit\n";
  const Outcome r = run_script(script);
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  const std::map<long, Row> after = placements_by_id(edited / "placements.csv");
  ASSERT_TRUE(after.count(pinned));
  EXPECT_NEAR(after.at(pinned).u, centre.u + 0.25 * D, 1e-5 * D) << "the dragged stone is where it was dropped";
  EXPECT_FALSE(after.count(deleted));
  long lost = 0;
  for (const auto& [id, row] : before) lost += id != deleted && !after.count(id);
  EXPECT_LE(lost, 3) << lost << " stones lost besides the deleted one";
  EXPECT_EQ(contact_violations(after), 0);

  // Half a spacing: the stone it lands on and the one in front go, no more (the issue's bound: at
  // most 2; its own edges' stones slid into their neighbours and lost 4).
  const fs::path half = dir_ / "half", half_script = dir_ / "half.txt";
  std::ofstream(half_script) << "open assets/surfaces/pendant.obj\ndesign assets/designs/pendant_tri_gems.json\noptimize\n"
                             << "select " << pinned << "\ndrag " << pinned << " 0.5 0\noptimize\nexport " << half.string()
                             << "\nquit\n";
  const Outcome h = run_script(half_script);
  ASSERT_EQ(h.exit_code, 0) << describe(h);
  const std::map<long, Row> dropped = placements_by_id(half / "placements.csv");
  ASSERT_TRUE(dropped.count(pinned));
  EXPECT_NEAR(dropped.at(pinned).u, centre.u + 0.5 * D, 1e-5 * D) << "the stone is not where it was dropped";
  long lost_half = 0;
  for (const auto& [id, row] : before) lost_half += !dropped.count(id);
  EXPECT_LE(lost_half, 2) << lost_half << " stones lost to a drag of half a spacing";
  EXPECT_EQ(contact_violations(dropped), 0);
}

// An element command on an element that is not there stops the script with a clear error.
TEST_F(StudioSession, AnElementCommandOnAMissingIdFails) {
  const fs::path script = dir_ / "missing.txt";
  std::ofstream(script) << "open assets/surfaces/pendant.obj\npin 99999999\n";
  const Outcome r = studio("--script " + quote(script.string()) + " --backend cpu --width 640 --height 480", dir_);
  EXPECT_EQ(r.exit_code, 2) << describe(r);
  EXPECT_NE(r.err.find("element 99999999 is not in the pavement on screen"), std::string::npos) << describe(r);
}

// A file that is not there is the user's input, not a bug: exit 2, as `paver run` (it was 1).
TEST_F(StudioSession, AMissingFileInAScriptExitsWithTwo) {
  for (const std::string& line : {std::string("design /nope/design.json"), std::string("open /nope/surface.obj")}) {
    const fs::path script = dir_ / "missing_file.txt";
    std::ofstream(script) << "open assets/surfaces/pendant.obj\n" << line << "\n";
    const Outcome r = studio("--script " + quote(script.string()) + " --backend cpu --width 640 --height 480", dir_);
    EXPECT_EQ(r.exit_code, 2) << line << "\n" << describe(r);
    EXPECT_NE(r.err.find("missing_file.txt:2: "), std::string::npos) << describe(r);
  }
}

// A command that waits for a pavement before any surface is open waited out the 10-minute timeout.
TEST_F(StudioSession, ACommandThatNeedsASurfaceBeforeAnyIsOpenFails) {
  for (const std::string& line : {std::string("optimize"), std::string("export out")}) {
    const fs::path script = dir_ / "no_surface.txt";
    std::ofstream(script) << line << "\nquit\n";
    const Outcome r = studio("--script " + quote(script.string()) + " --backend cpu --width 640 --height 480", dir_);
    EXPECT_EQ(r.exit_code, 2) << line << "\n" << describe(r);
    EXPECT_NE(r.err.find("no_surface.txt:1: " + line.substr(0, line.find(' ')) + " needs a surface"), std::string::npos)
        << describe(r);
  }
}

// The smallest spacing the pattern stage accepts on the pendant (2.7M elements) is beyond the
// studio's budget: a script stops at once with the figures instead of taking gigabytes and
// minutes (the window asks "run anyway?" instead).
TEST_F(StudioSession, ADesignBeyondTheBudgetIsRefusedBeforeItRuns) {
  const fs::path script = dir_ / "huge.txt";
  std::ofstream(script) << "open assets/surfaces/pendant.obj\nspacing 0.0162\noptimize\n";
  const Outcome r = studio("--script " + quote(script.string()) + " --backend cpu --width 640 --height 480", dir_);
  EXPECT_EQ(r.exit_code, 2) << describe(r);  // the design's fault, as for `paver run`
  EXPECT_NE(r.err.find("would place about 2,670,000 elements, above the studio's budget of"), std::string::npos)
      << describe(r);
  EXPECT_EQ(r.err.find("e+"), std::string::npos) << "figures for people, not scientific notation: " << describe(r);
  // optimize waits for a pavement of this design, which never ran.
  EXPECT_EQ(r.out.find("script 3: optimize"), std::string::npos) << "it ran: " << describe(r);
}

// The design given at launch is where undo stops: undo right after launch has nothing to undo
// (it used to swap in the built-in default).
TEST_F(StudioSession, UndoAfterLaunchKeepsTheLaunchDesign) {
  const fs::path script = dir_ / "undo.txt";
  std::ofstream(script) << "undo\n";
  const Outcome r = studio("assets/surfaces/dome.obj --design assets/designs/dome_hex_d6.json --script " +
                               quote(script.string()) + " --backend cpu --width 640 --height 480",
                           dir_);
  EXPECT_EQ(r.exit_code, 2) << describe(r);
  EXPECT_NE(r.err.find("undo: there is nothing to undo"), std::string::npos) << describe(r);
}

// The guidance brush: a dab painted looser in the middle of the pendant is saved with the design,
// thins the pattern there, and `paver run` on the saved design writes the same placements.
TEST_F(StudioSession, AGuidanceDabIsSavedAndTheCliReproducesIt) {
  const fs::path plain = dir_ / "plain", painted = dir_ / "painted", script = dir_ / "brush.txt";
  std::ofstream(script) << "open assets/surfaces/pendant.obj\n"
                           "design assets/designs/pendant_tri_gems.json\n"
                           "optimize\n"
                           "export " << plain.string() << "\n"
                        << "brush 0 0 5 0.4\n"
                           "optimize\n"
                           "export " << painted.string() << "\n";
  const Outcome r = run_script(script);
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  const nlohmann::json saved = nlohmann::json::parse(read_text(painted / "design.json"));
  ASSERT_EQ(saved["guidance"].size(), 1u);
  EXPECT_EQ(saved["guidance"][0]["strength"].get<double>(), 0.4);
  EXPECT_EQ(saved["pattern"]["topology"], "lattice");
  EXPECT_LT(placements_by_id(painted / "placements.csv").size(), placements_by_id(plain / "placements.csv").size());
  const fs::path cli_out = dir_ / "cli";
  const Outcome cli = run_in_source(quote(PAVER_CLI) + " run assets/surfaces/pendant.obj --design " +
                                        quote((painted / "design.json").string()) + " --backend cpu --out " +
                                        quote(cli_out.string()),
                                    dir_);
  ASSERT_EQ(cli.exit_code, 0) << describe(cli);
  EXPECT_TRUE(read_text(painted / "placements.csv") == read_text(cli_out / "placements.csv"));
}

// Add puts a vertex element at a map point (its id from 1e9 up), the stones around it make room,
// and pin then unpin leaves the element free again; both are undoable and saved in the design.
TEST_F(StudioSession, AddAndUnpinAreUndoableAndSaved) {
  ASSERT_NO_FATAL_FAILURE(pave_lattice_pendant());
  const fs::path base = dir_ / "base";
  const long some_id = placements_by_id(base / "placements.csv").rbegin()->first;
  const fs::path exported = dir_ / "added", script = dir_ / "add.txt";
  std::ofstream(script) << "open assets/surfaces/pendant.obj\n"
                           "set pattern.topology lattice\n"
                           "optimize\n"
                           "add 0.3 0.2\n"
                           "undo\n"
                           "redo\n"
                        << "pin " << some_id << "\n"
                        << "optimize\n"
                        << "export " << (dir_ / "pinned").string() << "\n"
                        << "unpin " << some_id << "\n"
                           "optimize\n"
                           "export " << exported.string() << "\n";
  const Outcome r = run_script(script);
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  const std::map<long, Row> after = placements_by_id(exported / "placements.csv");
  ASSERT_TRUE(after.count(1000000000)) << "the added element is missing";
  EXPECT_NEAR(after.at(1000000000).u, 0.3, 1e-6);  // placements.csv keeps float precision
  EXPECT_NEAR(after.at(1000000000).v, 0.2, 1e-6);
  EXPECT_EQ(contact_violations(after), 0);
  const nlohmann::json saved = nlohmann::json::parse(read_text(exported / "design.json"));
  ASSERT_EQ(saved["edits"]["added"].size(), 1u);
  EXPECT_EQ(saved["edits"]["added"][0]["id"].get<long>(), 1000000000);
  const nlohmann::json pinned = nlohmann::json::parse(read_text(dir_ / "pinned" / "design.json"));
  ASSERT_FALSE(pinned["edits"]["moved"].empty()) << "pin recorded nothing";
  for (const auto& moved : pinned["edits"]["moved"]) EXPECT_TRUE(moved["pinned"].get<bool>()) << moved.dump();
  ASSERT_EQ(saved["edits"]["moved"].size(), pinned["edits"]["moved"].size());
  for (const auto& moved : saved["edits"]["moved"]) EXPECT_FALSE(moved["pinned"].get<bool>()) << moved.dump();
}

// A box selection (Shift+drag in the 2D map; the script's select_box) takes every element in it,
// and Del deletes them all in one undo step: exactly those go, nothing else is lost.
TEST_F(StudioSession, ABoxSelectionIsDeletedInOneStep) {
  const fs::path before_dir = dir_ / "before", undone_dir = dir_ / "undone", after_dir = dir_ / "after",
                 script = dir_ / "box.txt";
  std::ofstream(script) << "open assets/surfaces/pendant.obj\n"
                           "set pattern.topology lattice\n"
                           "optimize\n"
                           "export " << before_dir.string() << "\n"
                        << "select_box -1.5 -1.5 1.5 1.5\n"
                           "delete selection\n"
                           "undo\n"
                           "optimize\n"
                           "export " << undone_dir.string() << "\n"
                        << "redo\n"
                           "optimize\n"
                           "export " << after_dir.string() << "\n";
  const Outcome r = run_script(script);
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  const std::map<long, Row> before = placements_by_id(before_dir / "placements.csv");
  const std::map<long, Row> after = placements_by_id(after_dir / "placements.csv");
  std::set<long> boxed;
  for (const auto& [id, row] : before)
    if (row.u >= -1.5 && row.u <= 1.5 && row.v >= -1.5 && row.v <= 1.5) boxed.insert(id);
  ASSERT_GE(boxed.size(), 3u);
  EXPECT_NE(r.out.find("selected " + std::to_string(boxed.size()) + "\n"), std::string::npos) << describe(r);
  for (const auto& [id, row] : before) EXPECT_EQ(after.count(id), boxed.count(id) ? 0u : 1u) << "element " << id;
  EXPECT_EQ(after.size() + boxed.size(), before.size());
  const nlohmann::json saved = nlohmann::json::parse(read_text(after_dir / "design.json"));
  EXPECT_EQ(saved["edits"]["deleted"].size(), boxed.size());
  // One undo step brings every one of them back.
  EXPECT_TRUE(read_text(undone_dir / "placements.csv") == read_text(before_dir / "placements.csv"));
}

// A designer's trial: a drag pins the stone, and P then un-pinned it (a toggle), so it slid back
// 0.3 D with nothing said. P pins, Shift+P lets go, and each says what it did.
TEST_F(StudioSession, ADragThenPKeepsTheStoneWhereItWasDroppedAndShiftPLetsGo) {
  ASSERT_NO_FATAL_FAILURE(pave_lattice_pendant());
  const fs::path base = dir_ / "base";
  const std::map<long, Row> before = placements_by_id(base / "placements.csv");
  const double D = nlohmann::json::parse(read_text(base / "design.json"))["pattern"]["spacing"].get<double>();
  const long dragged = nearest_vertex_element(before, 0, 0);
  const Row centre = before.at(dragged);
  const fs::path held = dir_ / "held", let_go = dir_ / "let_go", script = dir_ / "drag_p.txt";
  std::ofstream(script) << std::setprecision(17) << kMouseEditingOnTheLatticePendant
                        << "mouse_drag " << centre.u << " " << centre.v << " " << centre.u + 0.3 * D << " " << centre.v << "\n"
                        << "optimize\n"
                        << "key P\n"
                        << "optimize\n"
                        << "export " << held.string() << "\n"
                        << "key Shift+P\n"
                        << "optimize\n"
                        << "export " << let_go.string() << "\n";
  const Outcome r = run_script(script);
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  const std::map<long, Row> after = placements_by_id(held / "placements.csv");
  ASSERT_TRUE(after.count(dragged));
  EXPECT_NEAR(after.at(dragged).u, centre.u + 0.3 * D, 0.1 * D) << "P let the dragged stone slide back";
  const nlohmann::json kept = nlohmann::json::parse(read_text(held / "design.json"));
  ASSERT_EQ(kept["edits"]["moved"].size(), 1u) << kept["edits"].dump();
  EXPECT_TRUE(kept["edits"]["moved"][0]["pinned"].get<bool>()) << "P after a drag keeps the pin";
  EXPECT_NE(r.out.find("pinned element " + std::to_string(dragged)), std::string::npos) << "P says what it did: "
                                                                                          << describe(r);
  const nlohmann::json released = nlohmann::json::parse(read_text(let_go / "design.json"));
  ASSERT_EQ(released["edits"]["moved"].size(), 1u) << released["edits"].dump();
  EXPECT_FALSE(released["edits"]["moved"][0]["pinned"].get<bool>()) << "Shift+P lets go";
  EXPECT_NE(r.out.find("unpinned element " + std::to_string(dragged)), std::string::npos) << describe(r);
}

// The mouse and the keys, played into the window (not the script's element commands): E turns
// on editing, a click selects, a drag moves, P pins, Del deletes, Ctrl+click adds, Shift+drag
// selects a box; the exported pavement shows each.
TEST_F(StudioSession, TheMouseAndKeysEditStones) {
  ASSERT_NO_FATAL_FAILURE(pave_lattice_pendant());
  const fs::path base = dir_ / "base";
  const std::map<long, Row> before = placements_by_id(base / "placements.csv");
  const double D = nlohmann::json::parse(read_text(base / "design.json"))["pattern"]["spacing"].get<double>();
  // The vertex element nearest the map's middle is dragged; one three spacings left of it deleted.
  const long dragged = nearest_vertex_element(before, 0, 0);
  const Row centre = before.at(dragged);
  const long deleted = nearest_vertex_element(before, centre.u - 3 * D, centre.v);
  const Row gone = before.at(deleted);
  // And one three spacings right of it is pinned with P.
  const long pinned = nearest_vertex_element(before, centre.u + 3 * D, centre.v);
  const Row held = before.at(pinned);
  const double add_u = centre.u + 0.5 * D, add_v = centre.v - 3 * D;
  const fs::path exported = dir_ / "mouse", script = dir_ / "mouse.txt";
  std::ofstream(script) << std::setprecision(17) << kMouseEditingOnTheLatticePendant
                        << "mouse_drag " << centre.u << " " << centre.v << " " << centre.u + 0.4 * D << " " << centre.v << "\n"
                        << "optimize\n"
                        << "click " << held.u << " " << held.v << "\n"
                        << "key P\n"
                        << "click " << gone.u << " " << gone.v << "\n"
                        << "key Delete\n"
                        << "optimize\n"
                        << "click " << add_u << " " << add_v << " ctrl\n"
                        << "optimize\n"
                        << "export " << exported.string() << "\n";
  const Outcome r = run_script(script);
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  const std::map<long, Row> after = placements_by_id(exported / "placements.csv");
  // A pixel of the 2D view is about D / 10 on the pendant (ImGui floors the mouse to whole pixels).
  ASSERT_TRUE(after.count(dragged));
  EXPECT_NEAR(after.at(dragged).u, centre.u + 0.4 * D, 0.1 * D) << "the dragged stone is not where it was dropped";
  EXPECT_NEAR(after.at(dragged).v, centre.v, 0.1 * D);
  EXPECT_FALSE(after.count(deleted)) << "the stone clicked and deleted is still there";
  EXPECT_TRUE(after.count(1000000000)) << "Ctrl+click added nothing";
  const nlohmann::json saved = nlohmann::json::parse(read_text(exported / "design.json"));
  ASSERT_EQ(saved["edits"]["moved"].size(), 2u) << saved["edits"].dump();
  EXPECT_EQ(saved["edits"]["moved"][0]["id"].get<long>(), dragged);
  EXPECT_TRUE(saved["edits"]["moved"][0]["pinned"].get<bool>()) << "a dropped stone is held";
  EXPECT_EQ(saved["edits"]["moved"][1]["id"].get<long>(), pinned) << "P pinned another stone";
  EXPECT_TRUE(saved["edits"]["moved"][1]["pinned"].get<bool>());
  EXPECT_EQ(saved["edits"]["deleted"].size(), 1u);
  EXPECT_EQ(saved["edits"]["added"].size(), 1u);
  EXPECT_EQ(contact_violations(after), 0);

  // In the 3D view: the stone pressed on is dragged along the surface and dropped where the
  // cursor's ray meets it (the drag ends at the pixel of the surface point at the target).
  const fs::path dropped_dir = dir_ / "dropped3d", drop_script = dir_ / "drag3d.txt";
  const double to_u = centre.u - 0.5 * D, to_v = centre.v + 0.5 * D;
  std::ofstream(drop_script) << std::setprecision(17) << "open assets/surfaces/pendant.obj\n"
                             << "set pattern.topology lattice\n"
                             << "optimize\n"
                             << "key E\n"
                             << "mouse_drag3d " << dragged << " " << to_u << " " << to_v << "\n"
                             << "optimize\n"
                             << "export " << dropped_dir.string() << "\n";
  const Outcome drop = run_script(drop_script);
  ASSERT_EQ(drop.exit_code, 0) << describe(drop);
  const std::map<long, Row> dropped = placements_by_id(dropped_dir / "placements.csv");
  ASSERT_TRUE(dropped.count(dragged));
  // A pixel of the 3D view is about D / 15 here; the drop lands within a few.
  EXPECT_NEAR(dropped.at(dragged).u, to_u, 0.2 * D) << "the stone dragged in 3D is not where it was dropped";
  EXPECT_NEAR(dropped.at(dragged).v, to_v, 0.2 * D);
  EXPECT_GT(std::hypot(dropped.at(dragged).u - centre.u, dropped.at(dragged).v - centre.v), 0.4 * D) << "it did not move";
  const nlohmann::json drop_design = nlohmann::json::parse(read_text(dropped_dir / "design.json"));
  ASSERT_EQ(drop_design["edits"]["moved"].size(), 1u);
  EXPECT_TRUE(drop_design["edits"]["moved"][0]["pinned"].get<bool>());

  // A Shift+drag box around the middle, then Del: the box's stones go in one step.
  const fs::path boxed_dir = dir_ / "boxed", box_script = dir_ / "box_mouse.txt";
  std::ofstream(box_script) << std::setprecision(17) << "open assets/surfaces/pendant.obj\n"
                            << "set pattern.topology lattice\n"
                            << "optimize\n"
                            << "view2d\n"
                            << "key M\n"  // the map's u across the screen: the box on screen is the map's
                            << "key E\n"
                            << "mouse_drag -1.5 -1.5 1.5 1.5 shift\n"
                            << "key Delete\n"
                            << "optimize\n"
                            << "export " << boxed_dir.string() << "\n";
  const Outcome box = run_script(box_script);
  ASSERT_EQ(box.exit_code, 0) << describe(box);
  std::size_t inside = 0;
  for (const auto& [id, row] : before) inside += row.u >= -1.5 && row.u <= 1.5 && row.v >= -1.5 && row.v <= 1.5;
  const nlohmann::json box_design = nlohmann::json::parse(read_text(boxed_dir / "design.json"));
  // The box's corners land within a pixel of the map points: a stone on its edge may fall either way.
  EXPECT_NEAR(double(box_design["edits"]["deleted"].size()), double(inside), 2.0);
  EXPECT_GE(box_design["edits"]["deleted"].size(), 3u);
}

// Save (the file dialog's Save as) writes the design where asked, and never over a design bundled
// with Paver: the session stops with the reason and the bundled file is unchanged.
TEST_F(StudioSession, SaveAsWritesTheDesignAndNeverOverABundledOne) {
  const fs::path bundled = fs::path(PAVER_SOURCE_DIR) / "assets/designs/dome_hex_d6.json";
  const std::string before = read_text(bundled);
  const fs::path refused = dir_ / "refused.txt";
  std::ofstream(refused) << "design assets/designs/dome_hex_d6.json\n"
                            "set solver.dt 0.25\n"
                            "save assets/designs/dome_hex_d6.json\n";
  const Outcome no = studio("assets/surfaces/dome.obj --script " + quote(refused.string()) + " --backend cpu", dir_);
  EXPECT_NE(no.exit_code, 0) << describe(no);
  EXPECT_NE(no.err.find("is a design bundled with Paver"), std::string::npos) << describe(no);
  EXPECT_EQ(read_text(bundled), before);

  const fs::path mine = dir_ / "mine.json", script = dir_ / "save.txt";
  std::ofstream(script) << "design assets/designs/dome_hex_d6.json\n"
                           "set solver.dt 0.25\n"
                           "save " << mine.string() << "\n"
                        << "set solver.dt 0.5\n"
                           "design " << mine.string() << "\n";
  const Outcome r = studio("assets/surfaces/dome.obj --script " + quote(script.string()) + " --backend cpu", dir_);
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  const nlohmann::json saved = nlohmann::json::parse(read_text(mine));
  EXPECT_EQ(saved["solver"]["dt"].get<double>(), 0.25);
  EXPECT_EQ(saved["pattern"]["spacing"].get<double>(), 6.0) << "the loaded design, not the default";
  EXPECT_NE(read_text(dir_ / "config/paver/recent.txt").find(mine.string()), std::string::npos)
      << "a saved design is a recent file";
}

// A spacing larger than the part places nothing: the session says so and what to do, instead of
// showing 0 elements.
TEST_F(StudioSession, ASpacingLargerThanThePartSaysWhatToDo) {
  const fs::path script = dir_ / "large.txt";
  std::ofstream(script) << "open assets/surfaces/pendant.obj\nspacing 1000\noptimize\n";
  const Outcome r = studio("--script " + quote(script.string()) + " --backend cpu --width 640 --height 480", dir_);
  EXPECT_NE(r.exit_code, 0) << describe(r);
  EXPECT_NE(r.err.find("use a spacing below"), std::string::npos) << describe(r);
}

#ifdef PAVER_WITH_CGAL
// A closed bead cut across x (the script's cut_axis, the file panel's "cut across") exports what
// `paver run` writes from the exported design alone: the design keeps the axis
// (placement.cut_axis), so no --cut is needed to repeat it.
TEST_F(StudioSession, AClosedSurfaceCutAcrossAnAxisExportsWhatTheCliWrites) {
  const fs::path exported = dir_ / "export", script = dir_ / "bead.txt";
  std::ofstream(script) << "open assets/surfaces/bead.obj\n"
                           "cut_axis x\n"
                           "optimize\n"
                           "export " << exported.string() << "\n"
                        << "quit\n";
  const Outcome r = run_script(script);
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  ASSERT_TRUE(fs::is_regular_file(exported / "placements.csv")) << describe(r);
  expect_the_cli_lays_what_was_exported("assets/surfaces/bead.obj --design " + quote((exported / "design.json").string()),
                                        exported);
  EXPECT_EQ(nlohmann::json::parse(read_text(exported / "design.json"))["placement"]["cut_axis"], "x");
  const nlohmann::json report = nlohmann::json::parse(read_text(exported / "report.json"));
  EXPECT_EQ(report["surface"]["cut_normal"], nlohmann::json::array({1.0, 0.0, 0.0})) << report["surface"].dump();
}

// Rows along an axis and a fitted offset, set as the Placement section sets them: the studio lays
// what `paver run --align x --fit-offset` lays, byte for byte, and its exported design.json holds
// the turn and the offset found (align none, fit_offset false).
TEST_F(StudioSession, RowsAlongAnAxisWithAFittedOffsetExportWhatTheCliWrites) {
  const fs::path exported = dir_ / "export", script = dir_ / "facade.txt";
  std::ofstream(script) << "open assets/surfaces/facade_windows.obj\n"
                           "design assets/designs/facade_windows_grid_discs.json\n"
                           "set placement.align x\n"
                           "set placement.fit_offset true\n"
                           "optimize\n"
                           "export " << exported.string() << "\n"
                        << "quit\n";
  const Outcome r = run_script(script);
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  ASSERT_TRUE(fs::is_regular_file(exported / "placements.csv")) << describe(r);
  const nlohmann::json report = nlohmann::json::parse(read_text(exported / "report.json"));
  EXPECT_TRUE(report["pattern"]["row_alignment"].is_object()) << report["pattern"].dump();
  ASSERT_TRUE(report["pattern"]["offset_fit"].is_object()) << report["pattern"].dump();
  const nlohmann::json design = nlohmann::json::parse(read_text(exported / "design.json"));
  EXPECT_EQ(design["placement"]["align"], "none");
  EXPECT_EQ(design["placement"]["fit_offset"], false);
  EXPECT_EQ(design["placement"]["offset"], report["pattern"]["offset_fit"]["chosen"]["offset"]);
  expect_the_cli_lays_what_was_exported("assets/surfaces/facade_windows.obj --design "
                                        "assets/designs/facade_windows_grid_discs.json --align x --fit-offset",
                                        exported);
}

// The studio's Cut metal (in the background), with the stones set deeper and a table rule, writes
// the metal `paver run --subtract` writes for the same design and settings, byte for byte, and
// says NOT OK as the CLI does.
TEST_F(StudioSession, CutMetalWritesWhatTheCliSubtractWrites) {
  const fs::path cut = dir_ / "cut", exported = dir_ / "export", script = dir_ / "cut.txt";
  std::ofstream(script) << "open assets/surfaces/pendant.obj\n"
                           "pattern tri\n"
                           "set elements.vertex.shape gem\n"
                           "set elements.vertex.scale 0.9375\n"
                           "set elements.gap 0.1\n"
                           "spacing 1.6\n"
                           "optimize\n"
                           "export " << exported.string() << "\n"
                        // The stones set 0.1 deeper, their tables (0.255 above the girdle's middle
                        // for these 1.5 mm gems) then 0.155 high, over a ceiling of 0.15: NOT OK.
                        << "panel file\ntype \"seat depth\" 0.1\ntype \"table height\" 0.15\n"
                        << "cut 1 " << cut.string() << "\n"
                        << "quit\n";
  const Outcome r = run_script(script);
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  ASSERT_TRUE(fs::is_regular_file(cut / "cut.stl")) << describe(r);
  ASSERT_TRUE(fs::is_regular_file(cut / "cut.3mf"));
  EXPECT_NE(r.out.find("status: NOT OK: wrote "), std::string::npos) << describe(r);
  EXPECT_NE(r.out.find("tables more than 0.15 above the metal (--table-height; the highest 0.155"), std::string::npos)
      << describe(r);

  const fs::path cli_out = dir_ / "cli";
  const Outcome cli = run_in_source(quote(PAVER_CLI) + " run assets/surfaces/pendant.obj --design " +
                                    quote((exported / "design.json").string()) +
                                    " --backend cpu --subtract --thickness 1 --seat-depth 0.1 --table-height 0.15"
                                    " --formats ply --out " + quote(cli_out.string()),
                                dir_);
  ASSERT_EQ(cli.exit_code, 3) << describe(cli);
  const std::string studio_stl = read_text(cut / "cut.stl");
  EXPECT_GT(studio_stl.size(), 100000u);
  EXPECT_TRUE(studio_stl == read_text(cli_out / "cut.stl")) << "cut.stl differs from paver run --subtract's";
}
// A ring at its size from the studio: the inside diameter typed into Cut metal's field gives the
// metal paver run --subtract --inside-diameter gives, byte for byte, its finger side at 8.65 mm.
TEST_F(StudioSession, CutMetalMakesARingAtItsSizeAsTheCliDoes) {
  const fs::path cut = dir_ / "cut", exported = dir_ / "export", script = dir_ / "ring.txt";
  std::ofstream(script) << "open assets/surfaces/ring_band.obj\n"
                           "pattern tri\n"
                           "set elements.vertex.shape gem\n"
                           "set elements.vertex.scale 0.9375\n"
                           "set elements.gap 0.1\n"
                           // Known, open: with the spots closed (the default since issue 40) the
                           // studio's cut.stl and the CLI's differ, their placements equal; two
                           // studio runs differ from each other too (their stones.3mf equal but for
                           // UUIDs), the CLI's runs do not: something in the cut depends on more
                           // than its input there.
                           "set elements.close_spots false\n"
                           "spacing 1.6\n"
                           "optimize\n"
                           "export " << exported.string() << "\n"
                        << "panel file\ntype \"inside diameter mm\" 17.3\n"
                        << "cut 1.2 " << cut.string() << "\n"
                        << "quit\n";
  const Outcome r = run_script(script);
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  ASSERT_TRUE(fs::is_regular_file(cut / "cut.stl")) << describe(r);
  const fs::path cli_out = dir_ / "cli";
  const Outcome cli = run_in_source(quote(PAVER_CLI) + " run assets/surfaces/ring_band.obj --design " +
                                    quote((exported / "design.json").string()) +
                                    " --backend cpu --subtract --thickness 1.2 --inside-diameter 17.3 --formats ply --out " +
                                    quote(cli_out.string()),
                                dir_);
  ASSERT_EQ(cli.exit_code, 3) << "its spots left open: NOT OK " << describe(cli);
  EXPECT_NEAR(nlohmann::json::parse(read_text(cli_out / "report.json"))["cut"]["ring"]["inside_diameter_mm"].get<double>(),
              17.3, 1e-9);
  EXPECT_TRUE(read_text(exported / "placements.csv") == read_text(cli_out / "placements.csv")) << "the pavements differ";
  EXPECT_TRUE(read_text(cut / "cut.stl") == read_text(cli_out / "cut.stl")) << "cut.stl differs from paver run's";
}
#endif

TEST_F(StudioSession, AFailingCommandStopsTheSessionWithItsError) {
  const fs::path script = dir_ / "bad.txt";
  std::ofstream(script) << "open assets/surfaces/dome.obj\nset solver.nope 1\nquit\n";
  const Outcome r = studio("--script " + quote(script.string()) + " --backend cpu", dir_);
  EXPECT_EQ(r.exit_code, 2) << describe(r);
  EXPECT_NE(r.err.find("bad.txt:2: set solver.nope: no such design key"), std::string::npos) << describe(r);
}

TEST_F(StudioSession, ABadSurfaceIsReportedNotACrash) {
  const fs::path script = dir_ / "missing.txt";
  std::ofstream(script) << "open assets/surfaces/no_such_surface.obj\noptimize\n";
  const Outcome r = studio("--script " + quote(script.string()) + " --backend cpu", dir_);
  EXPECT_NE(r.exit_code, 0) << describe(r);
  EXPECT_NE(r.err.find("no_such_surface.obj"), std::string::npos) << describe(r);
}

TEST(StudioScript, ATypoFailsBeforeAnyWindowOpens) {
  const fs::path script = fs::temp_directory_path() / ("paver_studio_typo_" + std::to_string(getpid()) + ".txt");
  std::ofstream(script) << "open assets/surfaces/dome.obj\noptimise\n";
  const std::string command = quote(PAVER_STUDIO) + " --script " + quote(script.string()) + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::string output;
  char buffer[256];
  while (fgets(buffer, sizeof buffer, pipe)) output += buffer;
  const int status = pclose(pipe);
  fs::remove(script);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2) << output;
  EXPECT_NE(output.find(":2: unknown command 'optimise'"), std::string::npos) << output;
}

// Pixels of the bare-spot marks' red (255, 40, 90) in a screenshot's views: not the ratio scale's
// reds (no blue in them) nor the greys.
long spot_red_pixels(const fs::path& shot) {
  int width = 0, height = 0, channels = 0;
  unsigned char* pixels = stbi_load(shot.string().c_str(), &width, &height, &channels, 3);
  if (!pixels) return -1;
  long red = 0;
  for (int y = 60; y < height - 40; ++y)
    for (int x = 440; x < width; ++x) {
      const unsigned char* p = pixels + 3 * (long(y) * width + x);
      if (p[0] > 220 && p[1] < 90 && p[2] > 60 && p[2] < 140) ++red;
    }
  stbi_image_free(pixels);
  return red;
}

// A designer's trial: a dome at tri D 8 showed single-stone holes while the status said "ok: 481
// elements" and the views stayed green. The status line now counts the bare spots report.json
// counts for the same design, and the stones removed, and both views mark them (B hides them).
TEST_F(StudioSession, TheStatusAndBothViewsShowTheBareSpotsTheReportCounts) {
  const fs::path marked = dir_ / "marked.png", plain = dir_ / "plain.png", map = dir_ / "map.png";
  const fs::path script = dir_ / "session.txt", saved = dir_ / "design.json";
  // The closing fills the dome's holes now: left open here, they are what the views must show.
  std::ofstream(script) << "open assets/surfaces/dome.obj\npattern tri\nspacing 8\nset elements.close_spots false\n"
                        << "optimize\nwait 3\nscreenshot " << marked.string() << "\nview2d\nwait 3\nscreenshot " << map.string()
                        << "\nkey B\nwait 3\nscreenshot " << plain.string() << "\nsave " << saved.string() << "\nquit\n";
  const Outcome r = run_script(script);
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  // Touching stones on a tri lattice are pave: the verdict itself names the spots, NOT OK.
  const std::size_t at = r.out.rfind("status: NOT OK: ");
  ASSERT_NE(at, std::string::npos) << describe(r);
  const std::string status = r.out.substr(at, r.out.find('\n', at) - at);
  const std::size_t spots_at = status.find(" bare spot");
  ASSERT_NE(spots_at, std::string::npos) << "the holes are said: " << status;
  std::size_t digits = spots_at;
  while (digits > 0 && std::isdigit(static_cast<unsigned char>(status[digits - 1]))) --digits;
  const long said = std::stol(status.substr(digits, spots_at - digits));
  EXPECT_NE(status.find("removed where they still collided (marked in the views)"), std::string::npos) << status;

  // The same design on the CLI: report.json's count.
  const fs::path cli_out = dir_ / "cli";
  const Outcome cli = run_in_source(quote(PAVER_CLI) + " run assets/surfaces/dome.obj --design " +
                                        quote(saved.string()) + " --backend cpu --formats ply --out " +
                                        quote(cli_out.string()),
                                    dir_);
  ASSERT_EQ(cli.exit_code, 3) << "NOT OK for its spots, as the studio says: " << describe(cli);
  const nlohmann::json report = nlohmann::json::parse(read_text(cli_out / "report.json"));
  const long counted = report["quality_after"]["edges"]["bare_spots"].get<long>();
  EXPECT_GT(counted, 0) << "the issue's dome has holes to show";
  EXPECT_EQ(said, counted) << status;

  // Marked in the 3D view and in the 2D map; B takes the marks away.
  const long in_3d = spot_red_pixels(marked), in_2d = spot_red_pixels(map), hidden = spot_red_pixels(plain);
  ASSERT_GE(hidden, 0) << "cannot read " << plain;
  EXPECT_GT(in_3d, hidden + 40) << in_3d << " red mark pixels in 3D, " << hidden << " hidden";
  EXPECT_GT(in_2d, hidden + 40) << in_2d << " red mark pixels in 2D, " << hidden << " hidden";
}

// A designer's trial: stone diameter 0 + Enter reverted silently, "0-5" in D reverted on a click
// elsewhere, gap 99 mm on the pendant became D 99.8 and was refused as a spacing larger than the
// surface while the panel kept 99. Typed as a hand types them, each is refused at its field with
// its range, said on the status line, and the design does not change; a good value is taken.
TEST_F(StudioSession, ValuesTypedIntoFieldsAreRefusedAtTheFieldWithTheirRange) {
  const fs::path script = dir_ / "session.txt", before = dir_ / "before.json", after = dir_ / "after.json";
  const fs::path shot = dir_ / "refused.png";
  std::ofstream(script) << "open assets/surfaces/pendant.obj\ndesign assets/designs/pendant_tri_gems.json\noptimize\n"
                        << "save " << before.string() << "\npanel elements\n"
                        << "type \"stone diameter\" 0\ntype gap 99 tab\npanel pattern\n"
                        << "type \"D (spacing)\" 0-5 away\nwait 2\nscreenshot " << shot.string() << "\n"
                        << "save " << after.string() << "\ntype \"D (spacing)\" 2.5\nwait 2\nsave "
                        << (dir_ / "taken.json").string() << "\nquit\n";
  const Outcome r = run_script(script);
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  EXPECT_NE(r.out.find("status: refused: stone diameter '0': too small; give a value above 0 mm and below "),
            std::string::npos) << describe(r);
  EXPECT_NE(r.out.find("status: refused: gap '99': too large; give a value of at least 0 mm and below "),
            std::string::npos) << describe(r);
  EXPECT_NE(r.out.find("(D = stone + gap would be larger than the surface: the surface is about "), std::string::npos)
      << describe(r);
  EXPECT_NE(r.out.find("status: refused: D (spacing) '0-5': is not a number; give a value of at least 0 mm"),
            std::string::npos) << describe(r);
  EXPECT_EQ(r.out.find("error:"), std::string::npos) << "refused at the field, never a run's error: " << describe(r);
  EXPECT_EQ(read_text(before), read_text(after)) << "a refused value changes nothing";
  const nlohmann::json taken = nlohmann::json::parse(read_text(dir_ / "taken.json"));
  EXPECT_EQ(taken["pattern"]["spacing"].get<double>(), 2.5) << "a good value is taken";
  EXPECT_TRUE(fs::exists(shot));
}

// Stones graded towards a pendant's tip from the studio: the point is typed into its field (the
// middle box, y) and the pavement, saved, grades towards the surface's point nearest it.
TEST_F(StudioSession, StonesGradedTowardsAPointTypedIntoItsField) {
  const fs::path script = dir_ / "session.txt", exported = dir_ / "export";
  std::ofstream(script) << "open assets/surfaces/pendant.obj\npattern tri\nset elements.vertex.shape gem\n"
                           "set elements.vertex.scale 0.9375\nset elements.gap 0.1\nspacing 1.6\n"
                           "set elements.grade.smallest 1.1\nset elements.grade.width 8\n"
                           "set elements.grade.point [0,25.9,0]\nset elements.grade.by point\noptimize\n"
                           "panel elements\ntype \"towards the point\" 18\noptimize\nexport "
                        << exported.string() << "\nquit\n";
  const Outcome r = run_script(script);
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  const nlohmann::json saved = nlohmann::json::parse(read_text(exported / "design.json"))["elements"]["grade"];
  EXPECT_EQ(saved["by"], "point");
  EXPECT_EQ(saved["point"], nlohmann::json::array({0.0, 18.0, 0.0})) << saved.dump();
  const nlohmann::json report = nlohmann::json::parse(read_text(exported / "report.json"));
  EXPECT_EQ(report["grade"]["by"], "point");
  EXPECT_GT(report["grade"]["graded"].get<int>(), 10);
  // The small stones lie around the point typed, not the tip first given.
  std::ifstream csv(exported / "placements.csv");
  std::string line;
  std::getline(csv, line);
  double near_sum = 0, tip_sum = 0;
  int near = 0, tip = 0;
  while (std::getline(csv, line)) {
    std::vector<double> f;
    std::stringstream row(line);
    for (std::string cell; std::getline(row, cell, ',');) f.push_back(std::atof(cell.c_str()));
    ASSERT_GE(f.size(), 9u) << line;
    // Seen from above (the dome is one sheet over x, y): the point typed lies under the surface,
    // and the grade starts where the surface is nearest it, above it.
    const double x = f[2], y = f[3], diameter = f[8];
    if (std::hypot(x, y - 18) < 2.5) near_sum += diameter, ++near;
    if (std::hypot(x, y - 25.9) < 3) tip_sum += diameter, ++tip;
  }
  ASSERT_GT(near, 2);
  ASSERT_GT(tip, 0);
  EXPECT_LT(near_sum / near, 1.25) << "the stones at the point typed are the small ones";
  EXPECT_GT(tip_sum / tip, near_sum / near + 0.1) << "the tip first given is no longer the smallest";
}

// A designer's trial: a band's 2D view drew the placement's rotation ring larger than the band's
// strip, centred off it, though a band sets its rows' direction itself. No ring on a band: the
// view above the strip (framed in the middle) stays empty.
TEST_F(StudioSession, ABandsMapHasNoRotationRing) {
  const fs::path shot = dir_ / "band.png", script = dir_ / "session.txt";
  std::ofstream(script) << "open assets/surfaces/ring_band.obj\noptimize\nview2d\nwait 3\nscreenshot " << shot.string()
                        << "\nquit\n";
  const Outcome r = run_script(script);
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  int width = 0, height = 0, channels = 0;
  unsigned char* pixels = stbi_load(shot.string().c_str(), &width, &height, &channels, 3);
  ASSERT_TRUE(pixels) << "cannot read " << shot;
  long white = 0;  // the handles' white lines and square (the ring drew 224 such pixels here)
  for (int y = 120; y < 340; ++y)
    for (int x = 440; x < 980; ++x) {
      const unsigned char* p = pixels + 3 * (long(y) * width + x);
      const int lo = std::min({p[0], p[1], p[2]}), hi = std::max({p[0], p[1], p[2]});
      white += lo >= 195 && hi - lo < 20;
    }
  stbi_image_free(pixels);
  EXPECT_LT(white, 20) << white << " white pixels above the band's strip";
}

// The direction, in degrees (0 to 180, counter-clockwise from across), in which the bright part of
// a 1280x800 screenshot's large view (the surface and its stones, or the map and its disks) is
// longest: its pixels' principal axis. The toolbar, the scale bar, the legend, the gizmo and the
// status line are left out; the inset must be hidden (key I). -1 when the file cannot be read.
double long_axis_deg(const fs::path& shot) {
  int width = 0, height = 0, channels = 0;
  unsigned char* pixels = stbi_load(shot.string().c_str(), &width, &height, &channels, 3);
  if (!pixels) return -1;
  double n = 0, sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
  for (int y = 120; y < height - 45; ++y)
    for (int x = 440; x < width; ++x) {
      if ((x < 770 && y > 685) || (x > 1160 && y < 175)) continue;  // the legend, the gizmo
      const unsigned char* p = pixels + 3 * (long(y) * width + x);
      if (std::max({p[0], p[1], p[2]}) < 90) continue;  // the background
      n += 1, sx += x, sy += y, sxx += double(x) * x, syy += double(y) * y, sxy += double(x) * y;
    }
  stbi_image_free(pixels);
  if (n < 1000) return -1;
  const double cxx = sxx / n - (sx / n) * (sx / n), cyy = syy / n - (sy / n) * (sy / n),
               cxy = sxy / n - (sx / n) * (sy / n);
  // y runs down the image: the angle is measured with y up.
  double angle = 0.5 * std::atan2(-2 * cxy, cxx - cyy) * 180 / M_PI;
  return angle < 0 ? angle + 180 : angle;
}

// The difference of two such directions, 0 to 90 degrees.
double axis_difference_deg(double a, double b) {
  const double d = std::fmod(std::abs(a - b), 180.0);
  return std::min(d, 180 - d);
}

// A designer's trial: the 2D map lay turned 90 degrees from the 3D view. The map now lies as the
// 3D view shows the surface, follows it once an orbit comes to rest, and M keeps its u across.
TEST_F(StudioSession, TheMapLiesAsThe3dViewShowsTheSurface) {
  const fs::path script = dir_ / "turn.txt";
  std::ofstream out(script);
  out << "open assets/surfaces/pendant.obj\ndesign assets/designs/pendant_tri_gems.json\noptimize\nkey I\nkey E\n";
  const auto shots = [&](const std::string& name) {
    out << "view3d\nwait 3\nscreenshot " << (dir_ / (name + "_3d.png")).string() << "\nview2d\nwait 3\nscreenshot "
        << (dir_ / (name + "_2d.png")).string() << "\n";
  };
  shots("framed");
  out << "orbit 70 10\nwait 3\n";
  shots("orbited");
  out << "key M\nwait 3\n";
  shots("unturned");
  out << "orbit 70 10\nwait 3\n";
  shots("still");
  out << "quit\n";
  out.close();
  const Outcome r = run_script(script);
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  std::map<std::string, std::pair<double, double>> axes;  // 3D, 2D
  for (const char* name : {"framed", "orbited", "unturned", "still"}) {
    axes[name] = {long_axis_deg(dir_ / (std::string(name) + "_3d.png")), long_axis_deg(dir_ / (std::string(name) + "_2d.png"))};
    ASSERT_GE(axes[name].first, 0) << name;
    ASSERT_GE(axes[name].second, 0) << name;
  }
  // The pendant's long axis points the same way in both views, before and after the orbit.
  EXPECT_LT(axis_difference_deg(axes["framed"].first, axes["framed"].second), 12) << axes["framed"].first << " vs " << axes["framed"].second;
  EXPECT_LT(axis_difference_deg(axes["orbited"].first, axes["orbited"].second), 12)
      << axes["orbited"].first << " vs " << axes["orbited"].second;
  EXPECT_GT(axis_difference_deg(axes["framed"].second, axes["orbited"].second), 45) << "the map did not turn with the orbit";
  // M: the map as it was laid (u across), still while the 3D view turns.
  EXPECT_LT(axis_difference_deg(axes["unturned"].second, axes["still"].second), 2);
  EXPECT_GT(axis_difference_deg(axes["still"].first, axes["still"].second), 20) << "the case does not tell the two apart";
}

}  // namespace
