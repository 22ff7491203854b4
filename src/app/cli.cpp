// The stackbook program's command line (chapter 10). See cli.hpp.
#include "cli.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "stackbook/output/animated_gltf.hpp"
#include "stackbook/output/animated_svg.hpp"
#include "stackbook/output/contacts_csv.hpp"
#include "stackbook/output/output_files.hpp"
#include "stackbook/output/trajectory_csv.hpp"
#include "stackbook/output/viewer_html.hpp"
#include "stackbook/scene/scene.hpp"
#include "stackbook/scene/simulation.hpp"
#include "stackbook/peers/sweep_peers.hpp"
#include "stackbook/scene/sweep.hpp"

namespace stackbook::app {
namespace {

namespace fs = std::filesystem;

/// The scene the program runs when called without arguments.
constexpr const char* kDemoScene = "pyramid_2d";

const char* scenesDir() { return STACKBOOK_SCENES_DIR; }

/// One line on stderr: any byte a user put in a path or a name is escaped (printable()).
int reportError(const std::string& message, int code) {
  std::string line = printable(message);
  std::cerr << "stackbook: error: " << line << "\n";
  return code;
}

/// The loader's notes (what it repaired) and warnings (what is approximate), one line
/// each on stderr, also with --quiet: they say the run is not exactly the scene's files.
void printNotes(const Scene& scene) {
  for (const std::string& note : scene.notes) std::cerr << "stackbook: note: " << printable(note) << "\n";
  for (const std::string& warning : scene.warnings) std::cerr << "stackbook: warning: " << printable(warning) << "\n";
}

/// A scene argument: an existing file, else a bundled scene by name (with or without
/// ".json"). Throws SceneError if neither exists.
std::string resolveScene(const std::string& name) {
  std::error_code ec;
  if (fs::is_regular_file(name, ec)) return name;
  if (const std::string why = whyNotARegularFile(name); why != "no such file") {
    throw SceneError(name, "", "the scene is " + why);
  }
  if (name.find('/') == std::string::npos) {
    for (const std::string& candidate : {name, name + ".json"}) {
      const fs::path bundled = fs::path(scenesDir()) / candidate;
      if (fs::is_regular_file(bundled, ec)) return bundled.string();
    }
    throw SceneError(name, "", "no such scene file, and no bundled scene of that name (see `stackbook list`)");
  }
  throw SceneError(name, "", "no such scene file");
}

/// Draws "[#####.....]  45%  1234 steps/s  3.2 s left" on stderr, at most 10 times a second.
class ProgressBar {
 public:
  ProgressBar(bool enabled, double totalSteps)
      : enabled_(enabled), totalSteps_(totalSteps), start_(std::chrono::steady_clock::now()) {}
  void update(double fraction) {
    if (!enabled_) return;
    const auto now = std::chrono::steady_clock::now();
    if (fraction < 1.0 && now - last_ < std::chrono::milliseconds(100)) return;
    last_ = now;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const int width = 30;
    const int filled = static_cast<int>(std::lround(fraction * width));
    const double rate = elapsed > 0.0 ? fraction / elapsed : 0.0;  // of the run per second
    const double left = rate > 0.0 ? (1.0 - fraction) / rate : 0.0;
    char line[160];
    std::snprintf(line, sizeof line, "\r[%s%s] %3d%%  %8.0f steps/s  %6.1f s left ",
                  std::string(static_cast<std::size_t>(filled), '#').c_str(),
                  std::string(static_cast<std::size_t>(width - filled), '.').c_str(),
                  static_cast<int>(fraction * 100.0), rate * totalSteps_, left);
    std::cerr << line << std::flush;
    if (fraction >= 1.0) std::cerr << "\n";
  }

 private:
  bool enabled_;
  double totalSteps_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_{};
};

/// The output folder, created and tried with a small file before anything is simulated:
/// "" if it can be written, else the reason (one line naming the folder).
std::string probeOutputFolder(const fs::path& out) {
  std::error_code ec;
  const std::string name = "--out " + out.string();
  if (fs::exists(out, ec) && !fs::is_directory(out, ec)) return name + ": exists and is not a folder";
  fs::create_directories(out, ec);
  if (ec) return name + ": cannot create the folder: " + ec.message();
  const fs::path probe = out / (".stackbook-probe-" + std::to_string(::getpid()));
  {
    std::ofstream file(probe, std::ios::binary | std::ios::trunc);
    file << "probe\n";
    file.close();
    if (!file) {
      fs::remove(probe, ec);
      return name + ": cannot write files in the folder";
    }
  }
  fs::remove(probe, ec);
  return "";
}

/// Writes every output of `run` into `out` and returns the paths written.
std::vector<std::string> writeOutputs(const Scene& scene, const SceneRun& run, const fs::path& out,
                                      const nlohmann::json& summary) {
  std::vector<std::string> files;
  fs::create_directories(out);
  std::visit(
      [&](const auto& r) {
        using Result = std::decay_t<decltype(r)>;
        const std::string csv = (out / "trajectory.csv").string();
        writeTrajectoryCsv(r.recording, csv);
        files.push_back(csv);
        const std::string energy = (out / "energy.csv").string();
        writeEnergyCsv(r.recording, energy);
        files.push_back(energy);
        if (scene.output.contacts) {
          const std::string contacts = (out / "contacts.csv").string();
          writeContactsCsv(r.recording, contacts);
          files.push_back(contacts);
        }
        if constexpr (std::is_same_v<Result, RunResult<2>>) {
          const std::string svg = (out / "animation.svg").string();
          SvgOptions svgOptions;
          svgOptions.drawContacts = scene.output.drawContacts;
          writeAnimatedSvg(r.recording, svg, svgOptions);
          files.push_back(svg);
        } else {
          // Up is against gravity (the last axis, z, in a scene without gravity).
          const Vec3 g = std::get<SceneBodies<3>>(scene.bodies).world.gravity;
          GlbOptions glb;
          glb.up = g.norm() > 0.0 ? Vec3(-g.normalized()) : Vec3::UnitZ();
          glb.drawContacts = scene.output.drawContacts;
          const std::string glbPath = (out / "animation.glb").string();
          writeAnimatedGlb(r.recording, glbPath, glb);
          files.push_back(glbPath);
          ViewerOptions viewer;
          viewer.title = fs::path(scene.file).stem().string();
          const std::string html = (out / "viewer.html").string();
          writeViewerHtml(glbPath, html, viewer);
          files.push_back(html);
        }
      },
      run);
  const std::string summaryPath = (out / "summary.json").string();
  files.push_back(summaryPath);
  nlohmann::json full = summary;
  full["files"] = files;
  // A path may hold bytes that are not UTF-8: written as U+FFFD rather than failing.
  output_detail::writeFileOrThrow("summary", summaryPath,
                                  full.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
  return files;
}

struct RunArgs {
  std::string scene;
  std::string out;
  // Kept as the text the user wrote and checked with the scene, as --set values: "abc" or
  // 1e999 get the same one line at /dt as in the file, and no conversion saturates.
  std::optional<std::string> duration;
  std::optional<std::string> dt;
  std::optional<std::string> threads;
  std::vector<std::string> sets;
  bool quiet = false;
};

int runCommand(const RunArgs& args, bool demo) {
  std::string path;
  Scene scene;
  try {
    path = resolveScene(args.scene);
    std::vector<std::string> overrides = args.sets;
    if (args.dt) overrides.push_back("dt=" + *args.dt);
    if (args.duration) overrides.push_back("duration=" + *args.duration);
    if (args.threads) overrides.push_back("solver.threads=" + *args.threads);
    scene = loadScene(path, overrides);
  } catch (const SceneError& e) {
    return reportError(e.what(), kBadInput);
  }
  printNotes(scene);
  const fs::path out = args.out.empty() ? fs::path("stackbook-out") / fs::path(path).stem() : fs::path(args.out);
  if (const std::string problem = probeOutputFolder(out); !problem.empty()) return reportError(problem, kBadInput);
  try {
    ProgressBar bar(!args.quiet && isatty(fileno(stderr)) != 0, std::ceil(scene.duration / scene.settings.dt - 1e-9));
    RunOptions options;
    options.progress = [&bar](double fraction, double) { bar.update(fraction); };
    const SceneRun run = runScene(scene, options);
    nlohmann::json summary = runSummaryJson(scene, run);
    const std::vector<std::string> files = writeOutputs(scene, run, out, summary);
    summary["files"] = files;
    if (!args.quiet) std::cout << runSummaryText(summary);
    if (demo) {
      std::cout << "The demo's outputs are in " << fs::absolute(out).string() << "/; open "
                << (scene.dimension == 2 ? "animation.svg" : "viewer.html") << " there in a browser.\n";
    }
    if (!summary.at("finite").get<bool>()) return reportError("the run ended in a non-finite state", kRunFailed);
  } catch (const std::exception& e) {
    return reportError(e.what(), kRunFailed);
  }
  return kOk;
}

int listCommand() {
  std::vector<fs::path> files;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(scenesDir(), ec)) {
    if (entry.path().extension() == ".json") files.push_back(entry.path());
  }
  if (ec) return reportError(std::string("cannot list ") + scenesDir() + ": " + ec.message(), kRunFailed);
  std::sort(files.begin(), files.end());
  std::size_t width = 0;
  for (const fs::path& f : files) width = std::max(width, f.stem().string().size());
  std::cout << "Bundled scenes (" << scenesDir() << "):\n";
  for (const fs::path& f : files) {
    std::string description;
    try {
      const nlohmann::json doc = readSceneJson(f.string());
      description = doc.value("description", std::string("(no description)"));
    } catch (const std::exception& e) {
      description = std::string("(unreadable: ") + e.what() + ")";
    }
    std::cout << "  " << f.stem().string() << std::string(width + 2 - f.stem().string().size(), ' ')
              << description << "\n";
  }
  std::cout << "Run one with `stackbook run NAME`.\n";
  return kOk;
}

/// `stackbook check SCENE`: loads the scene as `run` would, without running it. With
/// `allDefects`, a refusal that has more to say (every defect of a refused mesh) prints it
/// after the one line, one item per line on stderr.
int checkCommand(const std::string& name, const std::vector<std::string>& sets, bool allDefects) {
  try {
    const std::string path = resolveScene(name);
    const Scene scene = loadScene(path, sets);
    printNotes(scene);
    std::cout << path << ": ok (" << scene.dimension << "D, " << scene.bodyCount() << " bodies, "
              << static_cast<long long>(std::ceil(scene.duration / scene.settings.dt - 1e-9)) << " steps of dt = "
              << scene.settings.dt << " s)\n";
  } catch (const SceneError& e) {
    const int code = reportError(e.what(), kBadInput);
    if (allDefects) {
      for (const std::string& line : e.details()) std::cerr << "  " << line << "\n";
    }
    return code;
  }
  return kOk;
}

struct SweepArgs {
  std::string spec;
  std::string csv;
  bool list = false;
  bool noPlot = false;
  bool plotOnly = false;
  int jobs = 2;
  std::vector<std::size_t> only;
};

/// `stackbook sweep SPEC`: the grid of runs of a sweep spec (chapter 11), resumed from the
/// CSV's rows, then the plots; `--list` prints each run as its own command line instead.
int sweepCommand(const SweepArgs& args) {
  SweepSpec spec;
  std::vector<SweepRun> runs;
  peers::registerSweepPeers();  // Box2D and Bullet, those this program was built with
  try {
    spec = loadSweepSpec(args.spec);
    spec.scene = resolveScene(spec.scene);
    runs = sweepRuns(spec);
  } catch (const SceneError& e) {
    return reportError(e.what(), kBadInput);
  }
  for (const std::string& note : sweepNotes(spec)) std::cerr << "note: " << note << "\n";
  const std::string csv =
      args.csv.empty() ? (fs::path("stackbook-out") / "sweeps" / (spec.name + ".csv")).string() : args.csv;
  if (args.list) {
    for (const SweepRun& run : runs) {
      std::cout << "stackbook sweep " << args.spec << " --csv " << csv << " --no-plot --jobs 1 --run " << run.index
                << "\n";
    }
    return kOk;
  }
  try {
    SweepOptions options;
    options.csvPath = csv;
    options.jobs = args.jobs;
    options.only = args.only;
    options.progress = [&](std::size_t done, std::size_t total, const SweepRow& row) {
      std::ostringstream line;
      line << "[" << done << "/" << total << "] run " << row.run.index << " "
           << (row.run.peer >= 0 ? row.run.engine + " " : std::string()) << row.run.knob << "="
           << row.run.value << (row.run.config == "-" ? "" : " " + row.run.config) << ": "
           << row.msPerSimulatedSecond << " ms per simulated s";
      for (std::size_t k = 0; k < row.errors.size(); ++k) line << ", " << spec.errors[k].name << " " << row.errors[k];
      std::cerr << line.str() << "\n";
    };
    if (!args.plotOnly) {
      const std::size_t made = runSweep(spec, options);
      std::cout << spec.name << ": " << made << " runs made, " << runs.size() - made << " already in " << csv << "\n";
    }
    if (!args.noPlot) {
      const std::string prefix = (fs::path(csv).parent_path() / spec.name).string();
      for (const std::string& svg : plotSweep(spec, csv, prefix)) std::cout << "  plot " << svg << "\n";
    }
  } catch (const SceneError& e) {
    return reportError(e.what(), kBadInput);
  } catch (const std::exception& e) {
    return reportError(e.what(), kRunFailed);
  }
  return kOk;
}

}  // namespace

int runCli(int argc, char** argv) {
  try {
    CLI::App app{
        "stackbook: rigid bodies with stacking (Guendelman, Bridson & Fedkiw 2003).\n"
        "Without arguments it runs the bundled demo scene and says where its outputs are."};
    app.name("stackbook");
    app.require_subcommand(0, 1);

    RunArgs run;
    CLI::App* runApp = app.add_subcommand("run", "Simulate a scene and write its outputs: trajectory.csv, "
                                                 "summary.json, and animation.svg (2D) or animation.glb with "
                                                 "viewer.html (3D)");
    runApp->add_option("scene", run.scene, "Scene file, or the name of a bundled scene (stackbook list)")
        ->required();
    runApp->add_option("--out,-o", run.out, "Output folder (default: stackbook-out/<scene name>)");
    // Checked with the scene (as --set duration=T and --set dt=H), so a bad value gets the
    // same one-line message as a bad value in the file.
    runApp->add_option("--duration", run.duration, "Simulated seconds (overrides the scene's duration)");
    runApp->add_option("--dt", run.dt, "Time step in seconds (overrides the scene's dt)");
    runApp->add_option("--threads", run.threads,
                       "Threads a step may use (overrides solver.threads; 0: every hardware thread, the "
                       "default). The result is the same for any number");
    runApp->add_option("--set", run.sets,
                       "Override a scene field before the checks: key=value, key a path like "
                       "solver.contactIterations or bodies.2.velocity, value JSON (repeatable)");
    runApp->add_flag("--quiet,-q", run.quiet, "No progress bar and no summary on the terminal");

    std::string checkScene;
    std::vector<std::string> checkSets;
    CLI::App* checkApp = app.add_subcommand("check", "Validate a scene file without running it");
    checkApp->add_option("scene", checkScene, "Scene file, or the name of a bundled scene")->required();
    checkApp->add_option("--set", checkSets, "Override a scene field (as for run)");
    bool checkAllDefects = false;
    checkApp->add_flag("--all-defects", checkAllDefects,
                       "After the one line of a refused mesh, list every defect it has, one per line");

    CLI::App* listApp = app.add_subcommand("list", "List the bundled scenes with their descriptions");

    SweepArgs sweep;
    CLI::App* sweepApp = app.add_subcommand(
        "sweep", "Run a sweep spec's grid of runs (chapter 11): one CSV row per run with its cost and errors, "
                 "resumed from the rows already there, then error-against-cost plots (gnuplot)");
    sweepApp->add_option("spec", sweep.spec, "Sweep spec file (JSON)")->required();
    sweepApp->add_option("--csv", sweep.csv, "CSV to append rows to (default: stackbook-out/sweeps/<name>.csv)");
    sweepApp->add_flag("--list", sweep.list, "Print each run as an independent command line and exit");
    sweepApp->add_option("--jobs,-j", sweep.jobs, "Runs at once (default 2)")->check(CLI::Range(1, 256));
    sweepApp->add_option("--run", sweep.only, "Only these run indices (repeatable)");
    sweepApp->add_flag("--no-plot", sweep.noPlot, "Write the CSV only");
    sweepApp->add_flag("--plot-only", sweep.plotOnly, "Draw the plots and the table from the CSV, running nothing");

    try {
      app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
      return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
      return app.exit(e);
    } catch (const CLI::ParseError& e) {
      return reportError(std::string(e.what()) + " (see stackbook --help)", kBadInput);
    }
    if (runApp->parsed()) return runCommand(run, false);
    if (checkApp->parsed()) return checkCommand(checkScene, checkSets, checkAllDefects);
    if (listApp->parsed()) return listCommand();
    if (sweepApp->parsed()) return sweepCommand(sweep);
    RunArgs demo;
    demo.scene = kDemoScene;
    std::cout << "Running the bundled demo scene \"" << kDemoScene << "\" (stackbook --help for more).\n";
    return runCommand(demo, true);
  } catch (const std::exception& e) {
    return reportError(e.what(), kRunFailed);
  }
}

}  // namespace stackbook::app
