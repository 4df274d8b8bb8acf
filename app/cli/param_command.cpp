// `paver param SURFACE [--out UV.obj]`: the bijective map alone (map_options_for), with its quality.
#include "command_line.h"
#include "commands.h"
#include "interrupt.h"
#include "progress.h"
#include "io/output_guard.h"

#include "map/bijective_map.h"
#include "core/input_error.h"
#include "core/number_text.h"
#include "core/printable.h"
#include "core/stopwatch.h"

#include <cctype>
#include "core/interrupted.h"
#include "mesh/mesh_loader.h"
#include "pipeline/map_surface.h"
#include "io/uv_map_export.h"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>

#include <filesystem>

namespace paver::cli {
namespace {

struct ParamArgs {
  std::string surface;
  std::string out;
  std::string start = "auto";
  int iterations = MapOptions{}.max_iterations;
  bool quiet = false;
};

int run_param(const ParamArgs& args) {
  nothing_written_yet();
  if (!args.out.empty()) {  // before any work
    std::error_code ec;
    if (std::filesystem::is_directory(args.out, ec))
      throw InputError("--out " + args.out + ": is a folder; paver param writes one map file: give its name, e.g. " +
                       (std::filesystem::path(args.out) / "uv.obj").string());
    refuse_overwriting_inputs({args.surface}, {args.out});
    check_output_file(args.out);
    // The map is written as an OBJ whatever the name says (a uv.ply held OBJ text).
    std::string extension = std::filesystem::path(args.out).extension().string();
    for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (extension != ".obj")
      throw InputError("--out " + args.out + ": paver param writes the map as an OBJ (its texture coordinates); " +
                       "give the file the .obj extension");
  }
  const Stopwatch load_watch;
  const LoadedSurface loaded = load_checked_surface(
      args.surface, [](const std::string& w) { std::cerr << "paver: warning: " << printable_cut(w, kMaxMessageBytes) << "\n"; });
  if (loaded.mesh.boundary_loops.empty())
    throw InputError(args.surface + ": is a closed surface; `paver param` maps one open surface, and `paver run` "
                     "cuts a closed one into charts (--cut)");
  const double load_ms = load_watch.milliseconds();
  const Stopwatch map_watch;
  // Said before the mapping, which can take minutes on a big mesh.
  std::printf("%s: %d vertices, %d faces, %d boundary vertices in %s (loaded in %.1f ms)\n",
              printable(args.surface).c_str(), loaded.mesh.vertex_count(), loaded.mesh.face_count(),
              boundary_vertex_count(loaded.mesh),
              count_text(long(loaded.mesh.boundary_loops.size()), "loop", "loops").c_str(),
              load_ms);
  std::fflush(stdout);

  MapOptions options = map_options_for(loaded.mesh);
  options.max_iterations = args.iterations;
  options.start = args.start == "lscm" ? MapStart::Lscm : args.start == "tutte" ? MapStart::Tutte : MapStart::Auto;
  // Ctrl-C ends the run at once until the map is written; progress on stderr.
  Progress progress(args.quiet, stderr_is_terminal());
  const Parameterization param = [&] {
    try {
      progress.stage("mapping");
      progress.fraction(0, "start map and factorization");
      std::optional<Parameterization> done = parameterize_surface(
          loaded.mesh, options,
          [&](int iterations, int max, double energy) {
            progress.fraction(double(iterations) / max, map_progress_text(iterations, max, energy));
          },
          [] { return interrupt_requested().load(); });
      progress.finish();
      if (!done) throw Interrupted();
      return std::move(*done);
    } catch (const InputError& e) {
      throw InputError(args.surface + ": " + e.what() + "; remesh the surface or remove its sliver triangles");
    }
  }();
  const double param_ms = map_watch.milliseconds();

  const auto& q = param.quality;
  std::printf("%s: %d iterations (%d factorization%s) in %.1f ms (%d steps shortened to stay bijective)\n",
              map_method_name(param.report).c_str(), param.report.iterations,
              param.report.factorizations, param.report.factorizations == 1 ? "" : "s", param_ms, param.report.blocked_steps);
  std::printf("  flipped triangles: %d, boundary self-intersections: %d -> %s\n", q.flipped_triangles,
              q.boundary_intersections, q.bijective() ? "bijective" : "NOT bijective");
  std::printf("  singular-value ratio s1/s2: mean %.4f, max %.4f\n", q.stretch_mean, q.stretch_max);
  std::printf("  area ratio 2D/3D: min %.4f, max %.4f, mean |ratio - 1| %.4f\n", q.area_ratio_min,
              q.area_ratio_max, q.area_distortion_mean);
  if (!args.out.empty()) {
    writing_starts();
    write_uv_map_obj(args.out, loaded.mesh, param.uv);
    std::printf("wrote %s\n", printable(args.out).c_str());
  }
  return q.bijective() ? 0 : 1;
}

}  // namespace

std::function<int()> add_param_command(CLI::App& app) {
  auto args = std::make_shared<ParamArgs>();
  CLI::App* cmd = app.add_subcommand("param", "Parameterize a surface (bijective: symmetric Dirichlet on a disk, ARAP with holes) and report its distortion");
  cmd->add_option("SURFACE", args->surface, "Open surface: OBJ, OFF, PLY or STL")->required();
  cmd->add_option("--out", args->out, "Write the map as an OBJ with the map as texture coordinates");
  cmd->add_option("--start", args->start, "Start map: auto (LSCM if bijective, else Tutte), lscm, tutte")
      ->check(CLI::IsMember({"auto", "lscm", "tutte"}))
      ->capture_default_str();
  cmd->add_option("--iterations", args->iterations, "Most map iterations")
      ->check(CLI::Range(0, 100000))
      ->capture_default_str();
  cmd->add_flag("--quiet", args->quiet, "No progress on stderr (warnings and errors still)");
  return [args] { return run_param(*args); };
}

}  // namespace paver::cli
