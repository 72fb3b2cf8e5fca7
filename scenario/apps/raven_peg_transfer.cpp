// raven_peg_transfer: the project's main job. Runs the peg transfer (or the paper's rectangle
// task D_II) on the in-process twin, headless, no ROS master: one run with a per-ring report, or
// a seeded randomised batch, split across machines with --shard, as JSON lines. With --over-ros
// the same job drives the twin node through the robot's ROS topics in lock-step.

#include <spdlog/fmt/fmt.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <atomic>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <thread>

#include "bridge/ros/ros_runtime.hpp"
#include "common/actuation_flag.hpp"
#include "common/number_checks.hpp"
#include "harness/ros_master.hpp"
#include "raven/design/arm_design.hpp"
#include "recording/cf_recording.hpp"
#include "scenario/batch.hpp"
#include "scenario/batch_summary.hpp"
#include "scenario/console_report.hpp"
#include "scenario/handover_reach.hpp"
#include "scenario/ros/peg_transfer_over_ros.hpp"
#include "scenario/run_watcher.hpp"
#include "scenario/task_views.hpp"

namespace {

namespace fs = std::filesystem;

/// Set by SIGINT or SIGTERM: the runs stop, and what finished is written.
std::atomic<bool> stop_requested{false};

extern "C" void requestStop(int /*signal*/) {
  stop_requested = true;
}

/// Command-line settings.
struct Settings {
  std::string task = "peg";
  std::uint64_t seed = 0;
  std::size_t runs = 1;
  std::string shard = "1/1";
  bool randomize = false;
  std::string ranges;  ///< with --randomize: a YAML of ranges; empty: the shipped ones
  std::string assist = "off";
  std::string launch;  ///< empty: the shipped peg-transfer scene
  std::size_t threads = 0;
  std::string out_dir = "peg_transfer_results";
  std::string record = "auto";
  std::string jsonl;
  /// The robot's motors, as every program's default; ideal servos on request.
  common::ActuationKind actuation = common::ActuationKind::Motors;
  std::string calibration;  ///< empty: the shipped profile
  double time_limit = 240.0;
  double squeeze_mm = scenario::ArmRoutine::kDefaultSqueeze * 1e3;
  double rect_width_mm = 0.0, rect_depth_mm = 0.0;  ///< 0: the task's default
  bool quiet = false, verbose = false;
  bool gui = false;
  std::string snapshot;                        ///< PREFIX: PREFIX_before.png and PREFIX_after.png
  std::vector<std::string> views{"overview"};  ///< of the snapshots
  common::VideoFlags video;                    ///< a batch: FILE_seed<N>.mp4
  std::string video_view = "overview";
  std::string video_first_frame;
  bool over_ros = false;
  scenario::ros1::OverRosOptions ros;
};

constexpr std::size_t kHandoverSamples = 100000;
/// The grasper jaw's length past the jaw axis (m).
const double kJawLength = raven::design::ArmDesign{}.jaw_length;

/// Logs go to stderr, so stdout holds only the report.
void setUpLogging(const Settings& s) {
  spdlog::set_default_logger(spdlog::stderr_color_mt("raven_peg_transfer"));
  spdlog::set_level(s.verbose ? spdlog::level::debug
                    : s.quiet ? spdlog::level::warn
                              : spdlog::level::info);
}

void writeJson(const fs::path& path, const nlohmann::json& j) {
  std::ofstream file(path);
  file << j.dump(2) << '\n';
  if (!file) throw std::runtime_error("cannot write " + path.string());
}

/// The window, the snapshots and the videos the settings ask for.
scenario::WatchOptions watchOptions(const Settings& s, bool batch) {
  scenario::WatchOptions w;
  w.window = s.gui;
  w.snapshot_prefix = s.snapshot;
  w.snapshot_views = s.views;
  w.video = s.video.file;
  w.video_per_seed = batch;
  w.video_options = viewer::VideoOptions::of(s.video);
  w.video_view = s.video_view;
  w.video_options.first_frame = s.video_first_frame;
  return w;
}

/// The runs' options from the command line (the seed, progress and watchers are per run).
scenario::PegTransferOptions pegTransferOptions(const Settings& s) {
  scenario::PegTransferOptions options;
  options.randomize = s.randomize;
  if (!s.ranges.empty()) options.ranges = scenario::readVariationRanges(s.ranges);
  options.assist =
      s.assist == "contact" ? scenario::AssistMode::Contact : scenario::AssistMode::Off;
  options.actuation = s.actuation;
  options.calibration = s.calibration;
  options.launch_file = s.launch;
  options.time_limit = s.time_limit;
  options.squeeze = s.squeeze_mm * 1e-3;
  options.stop = &stop_requested;
  return options;
}

/// The summary's fields besides the totals: what was asked for.
void describeBatch(const Settings& s, std::size_t asked, nlohmann::json& summary) {
  summary["task"] = "peg_transfer";
  summary["shard"] = s.shard;
  summary["first_seed"] = s.seed;
  summary["randomized"] = s.randomize;
  summary["grasp_assist"] = s.assist;
  summary["runs_asked"] = asked;
  summary["stopped"] = stop_requested.load();
}

/// The summary at the end: the totals of `finished` (of `asked`) and each run's results.
nlohmann::json summaryOf(const Settings& s, std::size_t asked,
                         const std::vector<scenario::PegTransferResult>& finished) {
  std::vector<nlohmann::json> rows;  // each run's JSON once: the totals and the results
  rows.reserve(finished.size());
  for (const auto& r : finished) rows.push_back(r.json());
  nlohmann::json summary = scenario::summarize(rows);
  describeBatch(s, asked, summary);
  summary["results"] = std::move(rows);
  return summary;
}

/// The line saying what runs: which seeds, which shard, which scene and actuation.
void printHeader(const Settings& s, const std::vector<std::uint64_t>& seeds,
                 const scenario::Shard& shard) {
  const std::string which = seeds.size() == 1 ? fmt::format("seed {}", seeds.front())
                                              : fmt::format("{} runs, seeds {}..{}", seeds.size(),
                                                            s.seed, s.seed + s.runs - 1);
  fmt::print(
      "Peg transfer on the Raven-II twin{}: {}{}, {} scene, grasp assist {}{}\n",
      s.over_ros ? " over ROS" : "", which,
      shard.count > 1 ? fmt::format(" (shard {}: every {}th from seed {})", s.shard, shard.count,
                                    s.seed + shard.index - 1)
                      : "",
      s.randomize ? "randomised" : "nominal", s.assist,
      s.actuation == common::ActuationKind::Motors ? ", motor-level actuation" : ", ideal servos");
  std::fflush(stdout);
}

/// Where a run's results go: the JSON lines, the summary, and whether rs files are written.
struct RunFiles {
  fs::path jsonl, summary;
  bool record = false;
};

/// Prints the table (one run's rings, or a batch's runs) and the handover line, and writes the
/// summary; the command's exit code.
int reportRuns(const Settings& s, const std::vector<scenario::PegTransferResult>& results,
               std::size_t asked, const RunFiles& files) {
  const bool single = asked == 1;
  const auto handover =
      scenario::measureHandoverReach(raven::builtinProfile("physical"), kHandoverSamples);
  if (single) {
    fmt::print("{}{}", scenario::ringTable(results.front()),
               scenario::timingLine(results.front().timing));
  } else {
    fmt::print("{}", scenario::batchTable(results));
  }
  fmt::print("mid-air handover: {}\n", handover.explain(kJawLength));

  nlohmann::json summary = summaryOf(s, asked, results);
  summary["handover"] = {
      {"possible", handover.possible(kJawLength)},   {"left_min_x_m", handover.left_min_x},
      {"right_max_x_m", handover.right_max_x},       {"gap_m", handover.gap()},
      {"samples_per_arm", handover.samples_per_arm}, {"explanation", handover.explain(kJawLength)}};
  writeJson(files.summary, summary);
  const auto& first = results.front();
  fmt::print("wrote {}{}, {}\n",
             single && files.record
                 ? fmt::format("{} ({} rows), {}, ", first.rs_file.string(), first.rs_rows,
                               recording::cfPathFor(first.rs_file).string())
                 : "",
             files.summary.string(), files.jsonl.string());
  if (stop_requested) return 130;
  // A run the world's guard stopped fails the command (the others are written all the same).
  return std::any_of(results.begin(), results.end(), [](const auto& r) { return r.failed(); }) ? 3
                                                                                               : 0;
}

int runPegTransfers(const Settings& s) {
  const scenario::Shard shard = scenario::Shard::parse(s.shard);
  const auto seeds = scenario::seedsOf(s.seed, s.runs, shard);
  if (s.runs > 1 && !s.randomize) {
    spdlog::warn("--runs {} without --randomize: every run uses the same nominal scene", s.runs);
  }
  const fs::path out(s.out_dir);
  fs::create_directories(out);
  const RunFiles files{s.jsonl.empty() ? shard.runsFile(out) : fs::path(s.jsonl),
                       shard.summaryFile(out),
                       s.record == "yes" || (s.record == "auto" && seeds.size() == 1)};
  std::ofstream jsonl(files.jsonl);
  if (!jsonl) throw std::runtime_error("cannot write " + files.jsonl.string());
  scenario::PegTransferOptions options = pegTransferOptions(s);
  std::signal(SIGINT, requestStop);
  std::signal(SIGTERM, requestStop);
  const bool single = seeds.size() == 1;
  printHeader(s, seeds, shard);

  scenario::ProgressBar bar(stderr, single ? "transfers" : "runs");
  std::vector<scenario::PegTransferResult> results;
  if (files.record) options.rs_folder = out;  // peg_transfer_seed<N>_rs.csv for every run
  scenario::RunWatcher watcher(watchOptions(s, !single));
  if (s.gui || !s.snapshot.empty() || !s.video.file.empty()) options.observe = std::ref(watcher);
  if (single) {
    options.seed = seeds.front();
    options.progress = [&bar](const scenario::RunProgress& p) { bar.show(p); };
    results.push_back(s.over_ros ? scenario::ros1::runPegTransferOverRos(options, s.ros)
                                 : scenario::runPegTransfer(options));
    jsonl << results.back().json().dump() << '\n' << std::flush;
  } else {
    // While it runs, the summary holds the totals so far (constant memory however many runs;
    // each run's row is in the runs file); the results join it at the end.
    scenario::RunTotals totals;
    std::size_t finished = 0;
    results = scenario::runBatch(
        options, seeds,
        s.threads > 0 ? s.threads : std::max(1u, std::thread::hardware_concurrency()),
        [&](const scenario::PegTransferResult& r) {
          const nlohmann::json row = r.json();
          jsonl << row.dump() << '\n' << std::flush;
          totals.add(row);
          nlohmann::json summary = totals.json();
          describeBatch(s, seeds.size(), summary);
          writeJson(files.summary, summary);
          bar.show({r.timing.sim_time, ++finished, seeds.size()});
        });
  }
  bar.finish();
  if (stop_requested) {
    const auto finished =
        std::count_if(results.begin(), results.end(), [](const auto& r) { return !r.stopped; });
    spdlog::warn(
        "stopped by a signal: {} of {} runs finished, {} cut short (\"stopped\": true); "
        "all are written",
        finished, seeds.size(), results.size() - static_cast<std::size_t>(finished));
  }
  if (results.empty()) return 130;
  return reportRuns(s, results, seeds.size(), files);
}

int runRectangleTask(const Settings& s) {
  const fs::path out(s.out_dir);
  fs::create_directories(out);
  scenario::RectangleOptions options;
  options.actuation = s.actuation;
  if (s.rect_width_mm > 0) options.width = s.rect_width_mm * 1e-3;
  if (s.rect_depth_mm > 0) options.depth = s.rect_depth_mm * 1e-3;
  if (s.record != "no") {
    options.rs_file = out / "rectangle_rs.csv";
    options.ci_file = out / "rectangle_ci.csv";
  }
  fmt::print(
      "Rectangle task D_II on the Raven-II twin: both arms, M2, sticks at full deflection\n");
  std::fflush(stdout);
  scenario::ProgressBar bar(stderr, "pad readings");
  options.progress = [&bar](const scenario::RunProgress& p) { bar.show(p); };
  const auto result = scenario::runRectangle(options);
  bar.finish();
  fmt::print("{}{}", scenario::rectangleSummary(result, options),
             scenario::timingLine(result.timing));
  const fs::path summary_path = out / "rectangle_summary.json";
  writeJson(summary_path, result.json());
  fmt::print("wrote {}{}\n",
             options.rs_file.empty()
                 ? ""
                 : fmt::format("{}, {}, ", options.rs_file.string(), options.ci_file.string()),
             summary_path.string());
  return 0;
}

void addOptions(CLI::App& app, Settings& s) {
  app.add_option("--task", s.task, "peg (the peg transfer, default) or rectangle (D_II)")
      ->check(CLI::IsMember({"peg", "rectangle"}));
  app.add_option("--seed", s.seed, "first seed (run k uses seed + k)");
  app.add_option("--runs", s.runs, "how many runs in the whole batch")
      ->check(common::finiteWithin(1, static_cast<double>(scenario::kMostRuns)));
  app.add_option("--shard", s.shard,
                 "i/N: run only this shard's share of the batch (runs k with k mod N = i - 1)");
  app.add_option("--randomize", s.ranges,
                 "draw ring start poses, ring friction and softness and board friction from the "
                 "seed: from the shipped ranges, or from RANGES.yaml's (docs/learning.md)")
      ->expected(0, 1)
      ->type_name("[RANGES.yaml]");
  app.add_option("--grasp-assist", s.assist,
                 "off (default: friction only) or contact (pin a ring touched by both jaws)")
      ->check(CLI::IsMember({"off", "contact"}))
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);  // quickstart.sh's can be overridden
  app.add_option(
         "--squeeze", s.squeeze_mm,
         fmt::format("how far the closed jaws reach into a ring's 4 mm wall (mm, default {})",
                     scenario::ArmRoutine::kDefaultSqueeze * 1e3))
      ->check(common::finiteWithin(0.0, 4.0));
  app.add_option("--launch", s.launch,
                 "the scene's launch file (default: the shipped peg_transfer/launch.yaml)")
      ->check(CLI::ExistingFile);
  app.add_option("--threads", s.threads, "worker threads for a batch (default: one per core)");
  app.add_option("--out", s.out_dir, "directory for the recordings and the summary");
  app.add_option("--record", s.record, "write rs files: auto (a single run only), yes or no")
      ->check(CLI::IsMember({"auto", "yes", "no"}));
  app.add_option("--jsonl", s.jsonl, "JSON-lines file, one line per run (default: in --out)");
  common::addActuationFlag(app, s.actuation);
  app.add_option("--calibration", s.calibration,
                 "the motors' calibration profile (raven_calibrate fit's YAML; default: the "
                 "shipped one)")
      ->check(CLI::ExistingFile);
  app.add_option("--time-limit", s.time_limit, "simulated seconds a run may take")
      ->check(common::kFinitePositive);
  app.add_option("--rect-width", s.rect_width_mm, "rectangle task: the side along x (mm)")
      ->check(common::kFinitePositive);
  app.add_option("--rect-depth", s.rect_depth_mm, "rectangle task: the side along y (mm)")
      ->check(common::kFinitePositive);
  app.add_option("-g,--show_gui", s.gui, "watch the run in a viewer window (AMBF's -g true)");
  app.add_flag("--gui", s.gui, "the same as -g true");
  app.add_option("--snapshot", s.snapshot,
                 "PREFIX: write PREFIX_before.png and PREFIX_after.png of a single run "
                 "(headless: no display needed)");
  const auto view_names = scenario::pegTransferViewNames();
  app.add_option("--views", s.views,
                 "the snapshots' views (several: PREFIX_<view>_before.png): overview, left-task, "
                 "right-task, grasper-left, grasper-right")
      ->check(CLI::IsMember(view_names))
      ->delimiter(',');
  common::addVideoFlags(app, s.video, "each run (a batch: FILE_seed<N>.mp4 per run)");
  app.add_option("--video-view", s.video_view, "the video's view (default overview)")
      ->check(CLI::IsMember(view_names));
  app.add_option("--video-first-frame", s.video_first_frame,
                 "FILE.png: the video's first frame as a picture too (a single run)");
  app.add_flag("--over-ros", s.over_ros,
               "drive the twin node through the robot's ROS topics in lock-step (started here "
               "unless --robot-namespace; a private rosmaster without ROS_MASTER_URI)");
  app.add_option(
         "--robot-namespace", s.ros.robot_namespace,
         "--over-ros: a twin node already serving the peg-transfer scene in lock-step there")
      ->needs("--over-ros");
  app.add_option("--twin-node", s.ros.twin_node,
                 "--over-ros: the raven_twin_node program to start (default: the built one)")
      ->check(CLI::ExistingFile)
      ->needs("--over-ros");
  app.add_flag("-q,--quiet", s.quiet, "warnings and errors only");
  app.add_flag("-v,--verbose", s.verbose, "log every phase of every transfer");
}

}  // namespace

int main(int argc, char** argv) {
  Settings s;
  CLI::App app{
      "raven_peg_transfer: the peg transfer (or the rectangle task D_II) on the Raven-II "
      "twin, headless; prints per-ring results and rates, writes the rs recording, a JSON "
      "summary and JSON lines"};
  addOptions(app, s);
  CLI11_PARSE(app, argc, argv);
  s.randomize = app.count("--randomize") > 0;
  setUpLogging(s);
  try {
    if ((s.gui || !s.snapshot.empty()) && (s.runs > 1 || s.task != "peg")) {
      spdlog::error("--gui and --snapshot watch a single peg transfer (no --runs, no --task)");
      return 2;
    }
    if (!s.calibration.empty() &&
        (s.actuation != common::ActuationKind::Motors || s.task != "peg")) {
      spdlog::error(
          "--calibration is the motors' profile for the peg transfer (--actuation motors)");
      return 2;
    }
    if (!s.video.file.empty() && s.task != "peg") {
      spdlog::error("--video records the peg transfer (not --task {})", s.task);
      return 2;
    }
    if (s.over_ros &&
        (s.runs > 1 || s.task != "peg" || s.gui || !s.snapshot.empty() || !s.video.file.empty())) {
      spdlog::error(
          "--over-ros runs a single peg transfer (no --runs, --task, --gui, "
          "--snapshot or --video)");
      return 2;
    }
    // Over ROS: a master of our own unless the environment names one.
    std::unique_ptr<harness::RosMaster> master;
    if (s.over_ros) {
      if (std::getenv("ROS_MASTER_URI") == nullptr) master = std::make_unique<harness::RosMaster>();
      int ros_argc = 1;
      char name[] = "raven_peg_transfer";
      char* ros_argv[] = {name, nullptr};
      bridge::ros1::initRos(ros_argc, ros_argv, "raven_peg_transfer_" + std::to_string(::getpid()),
                            false);
    }
    return s.task == "rectangle" ? runRectangleTask(s) : runPegTransfers(s);
  } catch (const std::invalid_argument& e) {
    spdlog::error("{}", e.what());
    return 2;
  } catch (const std::exception& e) {
    spdlog::error("{}", e.what());
    return 1;
  }
}
