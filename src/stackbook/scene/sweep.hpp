#pragma once
/// \file
/// \brief Parameter sweeps (chapter 11): a small JSON spec names a scene, the knobs to vary
/// and their values, and the error measures; the sweep runs the grid of runs (each
/// independent and deterministic), writes one CSV row per run with its cost and its errors,
/// resumes from the rows already written, and draws error against cost with gnuplot.
/// The format is the chapter's (\ref ch11_sweep).

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "stackbook/scene/simulation.hpp"

namespace stackbook {

// [sweep_spec]
/// One knob of a sweep: a scene field (a --set key such as `dt` or `solver.rotation`) and
/// the values it takes, each a JSON value.
struct SweepKnob {
  std::string key;
  std::vector<nlohmann::json> values;
};

/// One error measure of a run, computed from its recording (chapter 11):
/// - `position`, `velocity`, `angularVelocity`: component `axis` of body `body` at the end;
/// - `energyDrift`: the largest |E(t) - E(0)| over the frames, divided by |E(0)|;
/// - `maxPenetration`: the deepest interpenetration over the frames (m);
/// - `rollingStart`: the first frame time at which body `body` (a ball of `radius`) stops
///   slipping on a floor below it: |v + omega x (-radius up)| < `tolerance`;
/// - `flipPeriod`: twice the mean time between sign changes of component `axis` of body
///   `body`'s body-frame angular velocity (3D);
/// - `drift`: the largest horizontal distance (across gravity) of a dynamic body's centre
///   from its start, at the end (m);
/// - `sag`: how far body `body`'s centre moved along gravity from its start, at the end (m;
///   sinking and rising alike, since standing still is the answer).
/// - `bounceApex`: the height (along -gravity) of body `body`'s centre at its `apex`-th apex
///   (1, 2, ...): the vertex of the parabola through the apex-th interior local maximum of the
///   recorded heights and its two neighbours (sweepApexHeight()); a ball dropped from a gap
///   h with restitution e has its k-th apex at e^(2k) h above its resting height;
/// - `mirror`: the mirror error of a structure that starts symmetric about the plane through
///   its dynamic bodies' mean start position with normal `axis`: the largest distance between
///   a body's end position reflected in that plane and its mirror partner's end position (m;
///   sweepMirrorError()); 0 for a step that keeps the symmetry;
/// - `standing`: the seconds a structure stands: the first frame time at which some dynamic
///   body's centre is farther than `tolerance` (m) from its start, or the run's length if none
///   ever is. Higher is better: its Pareto front and its `within` (seconds, "at least") are
///   read that way (sweepHigherIsBetter());
/// - `windowed`: the self-consistency error of Erez, Tassa and Todorov (ICRA 2015): the mean
///   over `windows` windows of `window` seconds of the largest distance between a dynamic
///   body's centre in the run and in a run at dt / `refine`, each window restarted from the
///   fine run's state (m); chaos is then not counted as error;
/// - `distance`: how far body `body`'s centre ended from its start, |x(T) - x(0)| (m; the
///   distance a ball rolled down an incline, along whatever direction the slope has);
/// - `speed`: the magnitude of body `body`'s velocity at the end, |v(T)| (m/s);
/// - `rockingRatio`: the ratio r a rocking block keeps of its angular velocity at each
///   landing, from its centre's `apex`-th apex (as `bounceApex`) over its start height, both
///   above `rest`, the centre's height when the block lies flat: E_k / E_0 = r^(2k), so
///   r = ((y_k - rest) / (y_0 - rest))^(1 / (2k)) (sweepRockingRatio(); chapter 8, Eq. (8.20));
/// - `precession`: how far an axisymmetric body's symmetry axis (body axis `axis`, whose two
///   other principal moments must agree within `tolerance`, relative) strays from the closed
///   form of torque-free precession, which turns it about the fixed angular momentum L at
///   |L| / I1: the largest angle over the frames between the two axes, divided by the arc the
///   closed-form axis travels over the run, sin(cone angle) |L| T / I1 (sweepPrecessionError();
///   for a phase error alone this is the relative error of the precession angle; 3D).
/// With `expected` given the error is |value - expected|, divided by |expected| when
/// `relative` (the default), else the value itself.
struct SweepError {
  std::string name;
  std::string quantity;
  int body = 0;
  int axis = 0;
  double radius = 0.0;
  double tolerance = 1e-6;
  bool hasExpected = false;
  double expected = 0.0;
  bool relative = true;
  /// The accuracies the table of cheapest settings asks for (sweepParetoTable()): relative
  /// errors (against `expected`, and the relative-by-definition `energyDrift` and `precession`) as
  /// fractions, shown in percent (1e-2 is 1 %), absolute ones in `unit`.
  std::vector<double> within = {1e-2, 1e-3, 1e-4};
  std::string unit;  ///< of an absolute error, e.g. "m" (shown in the table)
  int windows = 10;      ///< `windowed`: how many windows
  double window = 0.1;   ///< `windowed`: each window's length (s)
  int refine = 16;       ///< `windowed`: the fine run's step is dt / refine
  int apex = 1;          ///< `bounceApex`, `rockingRatio`: which apex (1 is the first after the start)
  double rest = 0.0;     ///< `rockingRatio`: the centre's height at rest (m)
};

/// A peer engine's runs in a sweep: the engine (`box2d` in 2D, `bullet` in 3D) and its own
/// knobs (`dt`; Box2D's `velocityIterations` and `positionIterations`; Bullet's
/// `iterations`), run on the same scene with the same error measures.
struct SweepPeerSpec {
  std::string engine;
  std::vector<SweepKnob> knobs;
};

struct SweepSpec {
  std::string file;      ///< the spec's path
  std::string name;      ///< names the CSV and plots (default: the spec's stem)
  std::string scene;     ///< the scene's path (resolved against the spec's folder)
  std::string engine = "stackbook";
  std::vector<std::string> sets;  ///< fixed overrides of every run
  std::vector<SweepKnob> knobs;   ///< the first is plotted along each line, the rest make the lines
  std::vector<SweepError> errors;
  std::vector<SweepPeerSpec> peers;  ///< the `peers` field: Box2D or Bullet on the same scene
};
// [sweep_spec]

/// Reads and checks a sweep spec. Every problem is a SceneError naming the spec file, the
/// JSON pointer of the field and what is wrong (one line), like a scene file's.
SweepSpec loadSweepSpec(const std::string& path);
/// The same from a parsed document; `file` names it in messages.
SweepSpec parseSweepSpec(const nlohmann::json& document, const std::string& file);

// [sweep_run]
/// One run of the grid: its index, the overrides that make it, and its labels.
struct SweepRun {
  std::size_t index = 0;
  std::vector<std::string> overrides;  ///< spec.sets, then key=value for each knob
  std::string config;                  ///< the other knobs' key=value, joined by ';' ("-" if none)
  std::string knob;                    ///< the first knob's key
  std::string value;                   ///< its value as JSON text
  std::string engine = "stackbook";    ///< the CSV's engine column (a peer's label)
  int peer = -1;                       ///< index into spec.peers, -1 for stackbook
  /// A peer run's knob values (key, JSON value); stackbook's are in `overrides`.
  std::vector<std::pair<std::string, nlohmann::json>> peerKnobs;
};

/// The grid of runs: the Cartesian product of the knobs' values, the first knob varying
/// fastest, so that the runs of one line are adjacent; then each peer's grid, for every
/// peer that is built (sweepNotes() names the others).
std::vector<SweepRun> sweepRuns(const SweepSpec& spec);

/// One line per peer of the spec that is not built into this program (its runs are skipped).
std::vector<std::string> sweepNotes(const SweepSpec& spec);

/// The measured row of one run.
struct SweepRow {
  SweepRun run;
  std::int64_t steps = 0;
  double msPerStep = 0.0;
  double msPerSimulatedSecond = 0.0;
  std::vector<double> errors;  ///< one per spec error, in order
};

/// Loads the run's scene with its overrides (frames after every step when an error needs
/// them), runs it and measures every error. Cost is the step's own time (the counters'
/// totalSeconds), not the recording's. Throws SceneError for a bad override.
SweepRow runSweepRun(const SweepSpec& spec, const SweepRun& run);
// [sweep_run]

/// A run as engine-neutral frames, for the measures a peer's run shares with stackbook's:
/// every body's state in 3D (2D: the x-y plane, rotation and angular velocity about z).
struct SweepBodyState {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d angularVelocity = Eigen::Vector3d::Zero();  ///< world frame
};
struct SweepTrajectory {
  int dimension = 3;
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();
  std::vector<bool> isStatic;                        ///< per body
  std::vector<double> times;                         ///< per frame
  std::vector<std::vector<SweepBodyState>> frames;   ///< per frame, per body
  std::vector<double> energies;                      ///< per frame: kinetic + potential (-m g.x)
  /// Per body, the principal moments of inertia about its body axes (empty when the engine
  /// does not report them; the `precession` measure needs them).
  std::vector<Eigen::Vector3d> inertia;
  double maxPenetration = 0.0;                       ///< deepest overlap over the frames (m)
};
/// The error `e` of a run given as frames (what runSweepRun() measures for stackbook, from
/// the same definitions). Throws SceneError naming `file` when the body or axis does not exist.
double measureSweepTrajectory(const SweepError& e, const SweepTrajectory& t, const std::string& file);

/// Whether a larger value of the measure is the better one (`standing`); for every other
/// measure, an error, the smaller is.
bool sweepHigherIsBetter(const SweepError& e);

/// Whether the spec's errors need a frame after every step (energy drift, rolling start, flip
/// period, penetration, bounce apexes, standing, precession); otherwise the scene's own frame
/// rate is kept.
bool sweepNeedsEveryStep(const SweepSpec& spec);

/// The k-th apex (k >= 1) of a series of heights at increasing times: the k-th frame f with
/// heights[f-1] < heights[f] >= heights[f+1], refined to the vertex of the parabola through
/// the three (exact for a free flight under symplectic Euler, whose positions lie on a
/// parabola); +infinity if the series has fewer than k apexes.
double sweepApexHeight(const std::vector<double>& times, const std::vector<double>& heights, int k);

/// The `precession` error of an axisymmetric body in free flight (no torque): its body axis
/// `axis` is the symmetry axis, and its principal moments `inertia` must have the two others
/// equal within `tolerance` (relative; else a SceneError naming `file`). From the first frame's
/// orientation `rotations[0]` (body to world) and world angular velocity `omega0`, the angular
/// momentum is L = R0 diag(I) R0^T omega0 and the closed form turns the symmetry axis a0 about
/// L at the constant rate |L| / I1 (I1 the transverse moment): a(t) = Rot(L, |L| t / I1) a0.
/// The error is the largest angle over the frames between the body's axis and a(t), divided by
/// sin(angle between a0 and L) |L| T / I1, the arc a(t) travels over the run (T its length).
/// A SceneError if the spin is along the symmetry axis (nothing precesses) or the run is empty.
double sweepPrecessionError(const std::vector<double>& times, const std::vector<Eigen::Matrix3d>& rotations,
                            const Eigen::Vector3d& omega0, const Eigen::Vector3d& inertia, int axis,
                            double tolerance, const std::string& file);

/// The mirror error of a structure: every dynamic body's start position reflected in the plane
/// through their mean start position with unit normal `normal` must be another dynamic body's
/// start within `tolerance` (else a SceneError naming `file`); the error is the largest
/// distance between a body's end position, reflected, and its partner's end position.
double sweepMirrorError(const std::vector<Eigen::Vector3d>& start, const std::vector<Eigen::Vector3d>& end,
                        const std::vector<bool>& isStatic, const Eigen::Vector3d& normal, double tolerance,
                        const std::string& file);

/// A peer engine the sweep can run (stackbook_peers registers Box2D and Bullet when built).
struct SweepPeerEngine {
  std::string name;   ///< as in the spec: "box2d", "bullet"
  std::string label;  ///< the CSV's engine column: "Box2D 2.4.1", "Bullet 3.24"
  int dimension = 2;
  std::function<SweepRow(const SweepSpec&, const SweepRun&)> run;
};
/// Makes a peer available to sweepRuns() and runSweepRun() (replacing one of the same name).
void registerSweepPeer(SweepPeerEngine engine);
/// The registered peer of that name, or null.
const SweepPeerEngine* findSweepPeer(const std::string& name);

/// The CSV header: `run,scene,engine,config,knob,value,steps,ms_per_step,ms_per_simulated_second`
/// and one column per error, named as the error.
std::string sweepCsvHeader(const SweepSpec& spec);
/// One CSV line (with its newline) for a row.
std::string sweepCsvLine(const SweepSpec& spec, const SweepRow& row);
/// The run indices already present in a sweep CSV (empty if the file does not exist).
/// Throws SceneError if its header is not this spec's.
std::vector<std::size_t> completedRuns(const SweepSpec& spec, const std::string& csvPath);

/// What runSweep() does.
struct SweepOptions {
  std::string csvPath;             ///< where rows are appended
  int jobs = 2;                    ///< runs at once (each run single-threaded)
  std::vector<std::size_t> only;   ///< run just these indices (empty: all)
  /// Called after each finished run with (done, total, row).
  std::function<void(std::size_t, std::size_t, const SweepRow&)> progress;
};

/// Runs every run of the grid not yet in the CSV (resume), `jobs` at a time, and appends
/// their rows in index order. Returns the number of runs made.
std::size_t runSweep(const SweepSpec& spec, const SweepOptions& options);

/// The rows of a sweep CSV as text fields (header first).
std::vector<std::vector<std::string>> readSweepCsv(const std::string& csvPath);

/// Draws, for every error measure, the error against the cost (ms per simulated second),
/// log-log, one line per config with each point labelled by its knob value, and the Pareto
/// front (the runs no other run beats on both axes) marked: writes `<prefix>_<k>.dat` data,
/// `<prefix>.gp` and runs gnuplot on it, giving one SVG per error, `<prefix>_<error name>.svg`
/// (spaces as '_'), and the table of sweepParetoTable() as `<prefix>_pareto.md`. Returns the
/// SVG paths. Throws std::runtime_error if gnuplot fails.
std::vector<std::string> plotSweep(const SweepSpec& spec, const std::string& csvPath,
                                   const std::string& prefix);

/// The rocking ratio of a block whose centre started at heights[0] and rests at `rest`: r
/// from its k-th apex (sweepApexHeight()), ((y_k - rest) / (y_0 - rest))^(1 / (2k)); infinity
/// when there is no such apex.
double sweepRockingRatio(const std::vector<double>& times, const std::vector<double>& heights, int k, double rest);

/// A Markdown table of the cheapest stackbook run within each accuracy of each error measure
/// (SweepError::within: 1 %, 0.1 % and 0.01 % by default), with its setting and its cost,
/// and the cheapest peer run at the same accuracy, read from a sweep CSV; "none" where no
/// run gets there.
std::string sweepParetoTable(const SweepSpec& spec, const std::string& csvPath);

/// A knob value as a plot labels its point: a number in at most 4 significant digits, or, when
/// that would round it, as 1/n for a reciprocal of an integer (a time step of 1/60 s); any
/// other value (true, "samples") as written.
std::string sweepValueLabel(const std::string& value);

/// The table of sweepParetoTable() across several sweeps, one line per scene, error measure and
/// accuracy: the cheapest stackbook run and the cheapest peer run within that accuracy over every
/// sweep of the same scene file (matched by the file's name) with an error of the same name,
/// quantity and expected value, each named with its knob, its fixed `set` overrides and its
/// sweep. `csvPaths[k]` is the CSV of `specs[k]`.
std::string sweepSummaryTable(const std::vector<SweepSpec>& specs, const std::vector<std::string>& csvPaths);

/// The Pareto front of (cost, error) points: indices of the points no other point beats
/// on both (lower or equal cost and error, one strictly), sorted by cost.
std::vector<std::size_t> paretoFront(const std::vector<double>& cost, const std::vector<double>& error);

}  // namespace stackbook
