// `paver run SURFACE [--design F] [--pattern P] [--spacing D] [--out DIR]`: the whole pipeline.
#include "available_memory.h"
#include "backend_choice.h"
#include "command_line.h"
#include "commands.h"
#include "preview_images.h"
#include "interrupt.h"
#include "progress.h"
#include "run_summary.h"

#include "core/input_error.h"
#include "core/number_text.h"
#include "core/printable.h"
#include "core/stopwatch.h"
#include "design/design_keys.h"
#include "io/coordinate_precision.h"
#include "io/design_io.h"
#include "io/element_export.h"
#include "io/stl_unit_warning.h"
#include "pipeline/run_pipeline.h"
#include "report/ring_size.h"
#ifdef PAVER_WITH_CGAL
#include "cut/cut_outputs.h"
#include "cut/seat_rules.h"
#include "io/shape_table.h"
#include "report/verdict.h"
#endif

#include <charconv>
#include <cmath>
#include <cstdio>
#include <deque>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace paver::cli {
namespace {

namespace fs = std::filesystem;

// A design key's flag (design/design_keys.h), as given: a value, or a flag that takes none.
struct KeyFlag {
  Key key;
  std::optional<std::string> value;
  bool on = false;
  const CLI::Option* bool_flag = nullptr;  // a bool key's flag: "--close-spots", or "--no-close-spots"

  bool given() const { return value.has_value() || (bool_flag && bool_flag->count() > 0); }
  std::string text() const { return bool_flag ? (on ? "" : "false") : value.value_or(""); }
};

struct RunArgs {
  std::string surface;
  std::vector<std::string> region;
  std::string design;
  std::deque<KeyFlag> keys;  // a deque: CLI11 holds pointers into it
  std::optional<double> stone;
  std::vector<double> stone_sizes;  // --stone-sizes: the main stone, then the smaller stocked sizes
  std::string out = "out";
  bool no_optimize = false;
  bool no_postprocess = false;
  int threads = 0;
  bool no_resolve = false;
  bool no_refill = false;
  std::string backend = "auto";
  std::string device;
  bool png = false;
  double max_output_gb = 4;
  std::string formats = "ply,obj,glb,3mf";
  bool subtract = false;
  std::optional<double> thickness;
  std::optional<double> inside_diameter;  // mm
  std::vector<std::string> ring_size;     // system and size
  std::optional<double> culet_clearance, seat_wall, table_height;  // production rules of the cut (surface units)
  std::optional<double> seat_depth;  // the stones set this far below the surface in the cut (surface units)
  std::string cutter = "seat";
  bool quiet = false;

  const KeyFlag* flag(Key key) const {
    for (const KeyFlag& f : keys)
      if (f.key == key) return f.given() ? &f : nullptr;
    return nullptr;
  }
};

// `paver run` wrote its files but the verdict is NOT OK (docs/cli.md, "Exit codes").
constexpr int kExitVerdictNotOk = 3;

// A numeric flag that must be finite and > 0 (a size): its value, or an InputError naming the flag.
double finite_positive(const char* flag, double value, const char* meaning) {
  if (std::isfinite(value) && value > 0) return value;
  throw InputError(std::string(flag) + " " + number_text(value) + ": must be finite and > 0 (" + meaning + ")");
}

std::string flag_name(Key key) { return "--" + std::string(design_key(key).flag); }

// A flag's value in a message: a number as it was read ("NaN" for "-nan"), else the text, escaped.
std::string value_in_message(Key key, const std::string& text) {
  const KeyType type = design_key(key).type;
  double value = 0;
  if (type == KeyType::Number || type == KeyType::Integer) {
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error == std::errc() && end == text.data() + text.size()) return number_text(value);
  }
  return printable(text);
}

// The design's key flags over the file's, then --stone; a bad value blames the flag, not the
// design file. Returns the flags given ("--gap 0.1 --stone 1.5"), which a design error names with
// the file, since the fault may be theirs.
std::string apply_flags(const RunArgs& args, Design& design) {
  std::string given;
  const auto say = [&](const std::string& flag, const std::string& value) {
    given += (given.empty() ? "" : " ") + flag + (value.empty() ? "" : " " + printable(value));
  };
  for (const KeyFlag& f : args.keys) {
    if (!f.given()) continue;
    if (const std::optional<std::string> problem = set_key_from_text(design, f.key, f.text()))
      throw InputError(flag_name(f.key) + (f.text().empty() ? "" : " " + value_in_message(f.key, f.text())) + ": " +
                       *problem);
    say(f.bool_flag && !f.on ? "--no-" + std::string(design_key(f.key).flag) : flag_name(f.key),
        f.bool_flag ? "" : f.text());
  }
  std::optional<double> main_stone = args.stone;
  if (!args.stone_sizes.empty()) {
    if (args.stone) throw InputError("--stone and --stone-sizes both set the main stone (the first size): give one of them");
    if (args.flag(Key::fill_sizes))
      throw InputError("--stone-sizes and " + flag_name(Key::fill_sizes) +
                       " both set the smaller sizes (the sizes after the first): give one of them");
    for (const double size : args.stone_sizes) finite_positive("--stone-sizes", size, "stocked stone diameters, surface units");
    for (std::size_t k = 1; k < args.stone_sizes.size(); ++k)
      if (!(args.stone_sizes[k] < args.stone_sizes[0]))
        throw InputError("--stone-sizes: " + number_text(args.stone_sizes[k]) + " is not smaller than the first size, " +
                         number_text(args.stone_sizes[0]) + ", the main stone: list the sizes largest first");
    main_stone = args.stone_sizes[0];
    design.elements.fill_sizes.assign(args.stone_sizes.begin() + 1, args.stone_sizes.end());
    std::string list;
    for (const double size : args.stone_sizes) list += (list.empty() ? "" : ",") + number_text(size);
    say("--stone-sizes", list);
  }
  if (main_stone) {
    if (args.flag(Key::pattern_spacing))
      throw InputError("--stone and " + flag_name(Key::pattern_spacing) +
                       " both set the spacing (D = stone + gap): give one of them");
    const double stone = finite_positive("--stone", *main_stone, "the stone's diameter, surface units");
    set_stone_size(design, stone);
    // Pavé is a close packing: with no pattern asked for anywhere, stones go on a triangle lattice.
    if (!args.flag(Key::pattern_tessellation) && args.design.empty()) design.pattern.tessellation = Tessellation::Triangle;
    if (args.stone) say("--stone", number_text(*args.stone));
  }
  return given;
}

// What the flags do to a design they do not fit, said before the run.
void warn_about_flags(const RunArgs& args, const Design& design, const std::function<void(const std::string&)>& warn) {
  // Element edits name the elements of the layout they were made on: a flag that lays the pattern
  // out anew sends them to other elements, said before the run rather than found in its result.
  if (!design.edits.empty()) {
    std::string relaid;
    for (const Key key : {Key::pattern_tessellation, Key::pattern_topology, Key::pattern_spacing, Key::align})
      if (args.flag(key)) relaid += (relaid.empty() ? "" : ", ") + flag_name(key);
    if (!relaid.empty())
      warn(relaid + " lays the pattern out anew under this design's element edits, which name the elements of the "
           "layout they were made on: they may land on other elements (edit again after the change)");
  }
  // A size for elements that are not there: said, not dropped.
  if (args.flag(Key::face_scale) && !design.elements.face.enabled)
    warn(flag_name(Key::face_scale) + " sizes the F-elements, but this design places none: add " +
         flag_name(Key::face_enabled) + " (or set " + key_path(Key::face_enabled) + ")");
  if (args.flag(Key::grade_point) && design.elements.grade.by != GradeBy::Point)
    warn(flag_name(Key::grade_point) + " places a point grade, but the stones are graded by " +
         std::string(enum_name(design.elements.grade.by)) + ": add " + flag_name(Key::grade_by) + " point");
  // A design.json written by a run with --align holds the turn in rotation_deg already.
  if (const KeyFlag* align = args.flag(Key::align);
      align && design.placement.align != AlignAxis::None && design.placement.rotation_deg != 0 && !args.design.empty()) {
    char degrees[32];
    std::snprintf(degrees, sizeof degrees, "%.1f", design.placement.rotation_deg);
    warn(flag_name(Key::align) + " " + printable(align->text()) + ": " + args.design + " turns the pattern by " +
         key_path(Key::rotation_deg) + " " + degrees + " degrees on top of the alignment; a design.json written by a "
         "run with " + flag_name(Key::align) + " holds that run's turn there already, so give " + flag_name(Key::align) +
         " only to a design without it");
  }
}

// The request's design and its sources: the file, the flags over it, checked together.
void set_up_design(const RunArgs& args, PipelineRequest& request) {
  request.surface_path = args.surface;
  for (const std::string& name : args.region)
    if (name.empty()) throw InputError("--region has an empty name; give the OBJ group names, comma-separated");
  request.surface_region = args.region;
  request.design_source = args.design.empty() ? "defaults" : args.design;
  request.design_path = args.design;
  Design& design = request.design;
  if (!args.design.empty()) {
    std::vector<std::string> notes;
    design = load_design(args.design, &notes);
    for (const std::string& note : notes) request.on_warning(note);
  }
  request.design_overrides = apply_flags(args, design);
  warn_about_flags(args, design, request.on_warning);
  // What the flags and the file give together (c + m >= 0), named after where it came from.
  validate_design(design, args.design.empty() ? "command line" : args.design);
}

// A ring's finger side from --inside-diameter or --ring-size (mm), and the flag as given.
struct RingFinger {
  double inside_diameter_mm = 0;
  std::string given;
};

std::optional<RingFinger> ring_finger(const RunArgs& args) {
  if (args.inside_diameter && !args.ring_size.empty())
    throw InputError("--inside-diameter and --ring-size both set the ring's finger side: give one of them");
  std::optional<RingFinger> finger;
  if (args.inside_diameter)
    finger = RingFinger{finite_positive("--inside-diameter", *args.inside_diameter, "the ring's inside diameter, mm"),
                        "--inside-diameter " + number_text(*args.inside_diameter)};
  if (!args.ring_size.empty()) {
    const std::string given = "--ring-size " + printable(args.ring_size[0]) + " " + printable(args.ring_size[1]);
    const std::optional<RingSizeSystem> system = enum_from_name<RingSizeSystem>(args.ring_size[0]);
    if (!system) throw InputError(given + ": the size's system is US, EU or UK (--ring-size US 7)");
    finger = RingFinger{ring_inside_diameter_mm(*system, args.ring_size[1]), given};
  }
  if (finger && !args.subtract)
    throw InputError(finger->given + " sets the finger side of the metal that --subtract makes: add --subtract");
  return finger;
}

// --subtract: the flags checked now, the cut made with the other files (into `cut_summary`).
using ExtraWriter = std::function<void(const PipelineResult&, const fs::path&, StageTimings&, nlohmann::json&)>;
// Without CGAL only the flag checks run, so the other parameters go unused there.
ExtraWriter set_up_cut(const RunArgs& args, [[maybe_unused]] PipelineRequest& request,
                       [[maybe_unused]] Progress& progress, [[maybe_unused]] std::optional<PreviewImages>& previews,
                       [[maybe_unused]] nlohmann::json& cut_summary) {
  if (args.cutter != "seat" && args.cutter != "element")
    throw InputError("--cutter " + printable(args.cutter) + ": use seat (girdle, seat cone, hole through) or element");
  if (!args.subtract && args.thickness) throw InputError("--thickness is the metal's for --subtract: add --subtract");
  [[maybe_unused]] const std::optional<RingFinger> finger = ring_finger(args);
  const std::pair<const char*, const std::optional<double>*> cut_settings[] = {{"--culet-clearance", &args.culet_clearance},
                                                                              {"--seat-wall", &args.seat_wall},
                                                                              {"--table-height", &args.table_height},
                                                                              {"--seat-depth", &args.seat_depth}};
  for (const auto& [flag, value] : cut_settings) {
    if (!value->has_value()) continue;
    if (!args.subtract) throw InputError(std::string(flag) + " is a setting of the metal that --subtract cuts: add --subtract");
    if (!std::isfinite(**value))
      throw InputError(std::string(flag) + " " + number_text(**value) + ": must be a finite number (surface units)");
  }
  if (args.seat_depth && *args.seat_depth < 0)
    throw InputError("--seat-depth " + number_text(*args.seat_depth) +
                     ": how far below the surface the stones' girdles are set, 0 or more (surface units)");
  if (!args.subtract) return {};
  if (!args.thickness) throw InputError("--subtract needs --thickness T: how thick the metal is, surface units");
  // Checked in every build, so that a bad value says so before "this build has no CGAL".
  [[maybe_unused]] const double thickness =
      finite_positive("--thickness", *args.thickness, "the metal's thickness, surface units");
#ifdef PAVER_WITH_CGAL
  const fs::path out = args.out;
  // A ring at its size: the band checked once it is mapped, before the pattern.
  auto side = std::make_shared<std::optional<FingerSide>>();
  if (finger)
    request.check_map = [side, finger, thickness, per_mm = 1 / millimetres_per_unit(request.design.units)](
                            const SurfaceMap& map) {
      *side = check_finger_side(map, finger->inside_diameter_mm * per_mm, thickness, finger->given);
    };
  for (const std::string& name : cut_file_names()) request.extra_outputs.push_back(out / name);
  if (args.png) request.extra_outputs.push_back(out / "cut.png");
  const CutterKind cutter = *enum_from_name<CutterKind>(args.cutter);
  const auto warn = request.on_warning;
  const SeatRules rules{args.culet_clearance, args.seat_wall, args.table_height};
  const double seat_depth = args.seat_depth.value_or(0);
  return [&progress, &previews, &cut_summary, warn, thickness, cutter, side, rules, seat_depth](
             const PipelineResult& r, const fs::path& folder, StageTimings& timings, nlohmann::json& sections) {
    const CutOptions cut_options{.cutter = cutter, .thickness = thickness, .custom = r.custom_shape.get(),
                                 .stop = &interrupt_requested(), .beads = &r.pavement.beads,
                                 .finger_side = *side ? &**side : nullptr, .seat_depth = seat_depth};
    // Before the cut, which cannot report its progress: refused when it would not fit in memory,
    // and its size said (docs/benchmarks.md: it grows faster than the count).
    refuse_cut_beyond_memory(r.pavement.elements, cut_options, app::available_memory_bytes());
    progress.stage("cut: " + std::to_string(r.pavement.elements.size()) +
                   " cutters in one boolean, which reports no progress (3,933 took 105 s and 7,033 took 422 s "
                   "on 2 cores)");
    const Stopwatch watch;
    const CheckedCut checked = cut_and_check(*r.map, r.pavement.elements, cut_options, rules, r.pavement.design.units);
    const CutSolid& cut = checked.solid;
    write_cut_files(folder, cut, r.pavement.elements, r.custom_shape.get(), r.pavement.design.units,
                    &interrupt_requested());
    if (previews) previews->write_solid(folder / "cut.png", cut.mesh, r.map->mesh);
    timings.emplace_back("cut", watch.milliseconds());
    cut_summary = cut_json(cut, cutter, thickness, r.pavement.design.units);
    // The production rules: a broken one makes the verdict NOT OK, in report.json as in the summary.
    cut_summary["seats"] = seat_check_json(checked.seats);
    cut_summary["seats"]["problems"] = checked.problems;
    if (cut_options.finger_side) cut_summary["stones_stand_out_behind"] = std::max(0.0, -checked.seats.least_culet_metal);
    sections["cut"] = cut_summary;
    if (!checked.problems.empty()) {
      Verdict verdict = judge_pavement(r.pavement.after);
      verdict.ok = false;
      verdict.problems.insert(verdict.problems.end(), checked.problems.begin(), checked.problems.end());
      sections["verdict"] = to_json(verdict);
    }
    if (!checked.stand_out.empty()) warn(checked.stand_out);
    const std::string rounded = coordinate_rounding_warning(r.pavement.elements, "cut.stl", "cut.3mf and stones.3mf");
    if (!rounded.empty()) warn(rounded);
  };
#else
  throw InputError("--subtract: this paver was built without CGAL (-DPAVER_WITH_CGAL=OFF); rebuild with it");
#endif
}

// The stages on or off, the backend, the progress and the stop.
app::BackendChoice set_up_solving(const RunArgs& args, PipelineRequest& request, Progress& progress) {
  request.progress = progress.mapping();
  PavementOptions& options = request.pavement;
  options.on_stage = [&progress](const std::string& stage) { progress.stage(stage); };
  options.observer = progress.solver(request.design.solver.iterations);
  options.optimize = !args.no_optimize;
  options.postprocess = !args.no_postprocess;
  options.threads = args.threads;
  options.resolve_collisions = !args.no_resolve;
  options.refill = !args.no_refill;
  options.stop = &interrupt_requested();
  // NaN passes CLI11's range check (every comparison with it is false).
  if (!(args.max_output_gb >= 0.001 && args.max_output_gb <= 1e6))
    throw InputError("--max-output-gb " + number_text(args.max_output_gb) + ": must be a number from 0.001 to 1e6 (GB)");
  app::BackendChoice backend = app::choose_backend(args.backend, args.device, args.threads);
  options.solver = backend.factory;
  return backend;
}

// The files `paver run` writes, as the summary's last line lists them.
std::string written_files(const MeshFormats& formats, bool beads, bool cut, bool png) {
  std::string written = "placements.csv, stones.csv";
  for (const std::string& name : mesh_file_names(formats)) written += ", " + name;
  if (formats.stl && beads) written += ", beads.stl";
  written += ", design.json, report.json, report.html";
  if (cut)
    for (const std::string& name : cut_file_names()) written += ", " + name;
  if (cut && png) written += ", cut.png";
  if (png) written += ", preview.png, param.png";
  return written;
}

int run_run(const RunArgs& args) {
  nothing_written_yet();
  PipelineRequest request;
  const auto warn = [](const std::string& w) { std::cerr << "paver: warning: " << printable_cut(w, kMaxMessageBytes) << "\n"; };
  request.on_warning = warn;
  set_up_design(args, request);
  Progress progress(args.quiet, stderr_is_terminal());
  const app::BackendChoice backend = set_up_solving(args, request, progress);

  const fs::path out = args.out;
  request.out = out;
  request.max_output_bytes = args.max_output_gb * 1e9;
  try {
    request.formats = parse_mesh_formats(args.formats);
  } catch (const InputError& e) {
    throw InputError("--formats " + printable(args.formats) + ": " + e.what());
  }
  request.on_export = [&] {
    writing_starts();
    progress.stage("export");
  };
  std::optional<PreviewImages> previews;
  nlohmann::json cut_summary;
  const ExtraWriter write_cut = set_up_cut(args, request, progress, previews, cut_summary);
  if (args.png) {
    previews = PreviewImages::open();  // no device: refused now, before any work
    request.extra_outputs.insert(request.extra_outputs.end(), {out / "preview.png", out / "param.png"});
  }
  request.write_extras = [&](const PipelineResult& r, const fs::path& folder, StageTimings& timings,
                             nlohmann::json& sections) {
    if (write_cut) write_cut(r, folder, timings, sections);
    if (previews) {
      const Stopwatch watch;
      previews->write(folder, *r.map, r.pavement, r.custom_shape.get());
      timings.emplace_back("png", watch.milliseconds());
    }
  };
  std::vector<std::string> stl_files;
  if (request.formats.stl) stl_files.push_back("elements.stl");
  if (request.formats.stl && request.design.elements.beads.enabled) stl_files.push_back("beads.stl");
  if (args.subtract) stl_files.push_back("cut.stl");
  const std::string stl_units = stl_unit_warning(request.design.units, stl_files);
  if (!stl_units.empty()) warn(stl_units);
  const MeshFormats formats = request.formats;
  const PipelineResult result = run_pipeline(std::move(request));
  progress.finish();
  const SummaryContext summary{args.surface, backend.name, backend.device, cut_summary,
                               written_files(formats, result.pavement.beads.size() > 0, !cut_summary.is_null(), args.png),
                               out.string()};
  // The files are written either way (to look at); a script learns from the code that they failed.
  return print_run_summary(result, summary) ? 0 : kExitVerdictNotOk;
}

// The help of a design key's flag: its own line, with the key and its default.
std::string flag_help(const DesignKey& key) {
  const SolverParameter* solver = key.path.starts_with("solver.") ? find_solver_parameter(key.path.substr(7)) : nullptr;
  std::string help = std::string(key.path) + ": " + std::string(solver ? solver->help : key.help);
  if (key.type == KeyType::Choice) help += " (" + std::string(key.choices) + ")";
  help += " Default " + std::string(key.default_text);
  if (key.type == KeyType::Bool && key.default_text == "true") help += " (--no-" + std::string(key.flag) + " turns it off)";
  if (!key.unit.empty()) help += " (" + std::string(key.unit) + ")";
  return help;
}

void add_key_flags(CLI::App& cmd, RunArgs& args) {
  for (const Key key : flag_keys()) {
    const DesignKey& row = design_key(key);
    KeyFlag& slot = args.keys.emplace_back(KeyFlag{key, std::nullopt, false});
    const std::string flag = "--" + std::string(row.flag);
    // A bool key that is on by default is turned off by its --no- twin.
    const std::string names = row.type == KeyType::Bool && row.default_text == "true"
                                  ? flag + ",!--no-" + std::string(row.flag)
                                  : flag;
    CLI::Option* option = row.type == KeyType::Bool ? cmd.add_flag(names, slot.on, flag_help(row))
                                                    : cmd.add_option(flag, slot.value, flag_help(row));
    if (row.type == KeyType::Bool) slot.bool_flag = option;
    if (row.path.starts_with("solver.")) option->group("Solver (section 5)");
    if (row.type == KeyType::Number) option->type_name("NUMBER");
    if (row.type == KeyType::Integer) option->type_name("INT");
    if (row.type == KeyType::Choice) option->type_name("TEXT");
  }
}

}  // namespace

std::function<int()> add_run_command(CLI::App& app) {
  auto args = std::make_shared<RunArgs>();
  CLI::App* cmd = app.add_subcommand("run", "Pave a surface: map, pattern, elements, export and report");
  cmd->add_option("SURFACE", args->surface, "Surface: OBJ, OFF, PLY or STL (open, or closed without handles)")->required();
  cmd->add_option("--design", args->design, "design.json (flags below override it)");
  add_key_flags(*cmd, *args);
  cmd->add_option("--stone", args->stone,
                  "Stone diameter, surface units: the vertex elements become round brilliants of this size, with "
                  "D = stone + gap so that neighbouring stones are exactly the gap apart (instead of --spacing)");
  cmd->add_option("--stone-sizes", args->stone_sizes,
                  "Stocked stone diameters, largest first, comma-separated: the first as --stone, and what it leaves "
                  "filled with the largest of the others that fits (" + key_path(Key::fill_sizes) + ")")
      ->delimiter(',');
  cmd->add_option("--out", args->out, "Output folder")->capture_default_str();
  cmd->add_option("--region", args->region,
                  "Pave only these named parts of the surface (OBJ 'g' or 'o' names, comma-separated), their borders "
                  "as rims: a solid ring's outer face")
      ->delimiter(',');
  cmd->add_flag("--no-optimize", args->no_optimize, "Skip the section 5 optimizer (initial pavement only)");
  cmd->add_flag("--no-postprocess", args->no_postprocess, "Skip boundary filling and elimination (5.4)");
  cmd->add_option("--threads", args->threads, "Solver threads (0 = all cores; no more than the cores are used)")->check(CLI::Range(0, 1024));
  app::add_backend_option(*cmd, args->backend);
  cmd->add_option("--device", args->device, "Vulkan device: a substring of its name (see `paver devices`)");
  cmd->add_flag("--quiet", args->quiet, "No progress on stderr (warnings and errors still)");
  cmd->add_option("--formats", args->formats,
                  "Mesh files to write, comma-separated: ply, obj, stl, glb (glTF 2.0 binary), 3mf")
      ->capture_default_str();
  cmd->add_flag("--subtract", args->subtract,
                "Also write the metal with the stones' seats cut out (cut.stl, cut.3mf), the stones alone (stones.3mf) "
                "and the metal's weight; needs --thickness");
  cmd->add_option("--thickness", args->thickness, "Metal thickness for --subtract, surface units (against the normals)");
  cmd->add_option("--inside-diameter", args->inside_diameter,
                  "A band's ring size for --subtract, mm: the metal's finger side a cylinder this wide, --thickness "
                  "then its least thickness");
  cmd->add_option("--ring-size", args->ring_size, "The same as a ring size: US 7, EU 54 or UK N1/2")
      ->expected(2)
      ->type_name("SYSTEM SIZE");
  // The cut's production rules: a stone that breaks one makes the run NOT OK.
  for (const auto& [flag, value, rule] : {std::tuple{"--culet-clearance", &args->culet_clearance,
                                                     "at least this much metal under every stone's culet"},
                                          std::tuple{"--seat-wall", &args->seat_wall,
                                                     "at least this much metal between two seats at their girdles"},
                                          std::tuple{"--table-height", &args->table_height,
                                                     "no stone's table more than this above the metal's surface"}})
    cmd->add_option(flag, *value,
                    std::string("A rule for --subtract: ") + rule +
                        " (surface units); a stone that breaks it makes the run NOT OK");
  cmd->add_option("--seat-depth", args->seat_depth,
                  "For --subtract: set the stones this far below the surface (their girdles; surface units, default 0): "
                  "the seats are cut that deep and stones.3mf holds them there");
  cmd->add_option("--cutter", args->cutter, "What --subtract cuts: seat (girdle, seat cone, hole through) or element")
      ->capture_default_str();
  cmd->add_flag("--png", args->png, "Also render preview.png (3D) and param.png (2D) offscreen with Vulkan");
  cmd->add_option("--max-output-gb", args->max_output_gb,
                  "Refuse to write element meshes (PLY + OBJ) larger than this, in GB")
      ->check(CLI::Range(0.001, 1e6))
      ->capture_default_str();
  cmd->add_flag("--no-resolve", args->no_resolve, "Skip the contact-spring collision resolution (with --no-refill: the paper's method only)");
  cmd->add_flag("--no-refill", args->no_refill, "Leave bare regions bare (no elements added where the pattern tore)");
  return [args] { return run_run(*args); };
}

}  // namespace paver::cli
