// ambf_like: load AMBF launch/ADF/URDF files into Bullet and run the dynamic loop headless.

#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <atomic>
#include <chrono>
#include <csignal>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "ambf_like/physics_loop.hpp"
#include "ambf_like/scene_loader.hpp"
#include "ambf_like/world.hpp"
#include "common/number_checks.hpp"
#include "viewer/snapshot_schedule.hpp"
#include "viewer/video_recorder.hpp"
#include "viewer/viewer.hpp"

namespace {

std::atomic<bool> g_stop{false};

/// Everything the command line can set.
struct Options {
  std::string launch_file;
  std::string launch_indices;
  std::vector<std::string> extra_files;
  std::string world_file;
  double rate_hz = 1.0 / ambf_like::kAmbfStepSize;
  bool fixed_time_step = false;
  bool free_run = false;
  bool show_gui = false;
  std::uint64_t max_steps = 0;
  double duration = 0.0;
  double step_size = ambf_like::kAmbfStepSize;
  bool strict = false;
  std::string summary_json;
  bool quiet = false;
  std::string snapshot;
  double snapshot_every = 0.0;
  common::VideoFlags video;
  std::string visual_skin;
  bool collision_view = false;
  bool contacts = false;
};

ambf_like::LoadedScene load(const Options& o) {
  ambf_like::LoadOptions options;
  options.strict = o.strict;
  std::vector<std::filesystem::path> extras(o.extra_files.begin(), o.extra_files.end());
  if (!o.launch_file.empty()) {
    ambf_like::LaunchSelection selection;
    if (!o.launch_indices.empty())
      selection.indices = ambf_like::parseLaunchIndices(o.launch_indices);
    selection.extra_files = extras;
    return ambf_like::loadLaunchFile(o.launch_file, selection, options);
  }
  std::optional<std::filesystem::path> world;
  if (!o.world_file.empty()) world = std::filesystem::path(o.world_file);
  return ambf_like::loadModelFiles(extras, world, options);
}

/// The run's summary; `diverged` is the guard's reason when the world blew up (then it says
/// `finite: false` with that reason, whatever the nodes hold now).
nlohmann::json summarize(const ambf_like::LoadedScene& scene, const ambf_like::World& world,
                         const ambf_like::FrequencyMeter& meter, double wall_seconds,
                         const std::optional<std::string>& diverged) {
  std::size_t static_bodies = 0, controllable = 0;
  for (std::size_t i = 0; i < world.bodyCount(); ++i) static_bodies += world.body(i).isStatic();
  for (std::size_t i = 0; i < world.jointCount(); ++i)
    controllable += world.joint(i).isControllable();
  nlohmann::json models = nlohmann::json::array();
  for (const auto& m : scene.spec.models) models.push_back(m.file.string());
  const double iterations = static_cast<double>(meter.iterations());
  return {
      {"models", models},
      {"rigid_bodies", world.bodyCount()},
      {"static_bodies", static_bodies},
      {"soft_bodies", world.softBodyCount()},
      {"joints", world.jointCount()},
      {"controllable_joints", controllable},
      {"articulations", world.articulationCount()},
      {"collision_vertices", world.collisionVertexCount()},
      {"collision_primitives", world.collisionPrimitiveCount()},
      {"warnings", scene.warnings.size()},
      {"steps", world.stepCount()},
      {"step_size_s", world.stepSize()},
      {"sim_time_s", world.time()},
      {"wall_time_s", wall_seconds},
      {"real_time_factor", wall_seconds > 0 ? world.time() / wall_seconds : 0.0},
      {"loop_iterations", meter.iterations()},
      {"loop_frequency_hz",
       {{"mean", wall_seconds > 0 ? iterations / wall_seconds : 0.0},
        {"window_min", meter.minimum()},
        {"window_max", meter.maximum()},
        {"windows", meter.completedWindows()}}},
      {"finite", !diverged && world.isFinite()},
      {"failure", diverged ? nlohmann::json(*diverged) : nlohmann::json(nullptr)},
  };
}

void printSummary(const nlohmann::json& s) {
  std::printf("\nambf_like summary\n");
  std::printf("  models            : %zu\n", s["models"].size());
  for (const auto& m : s["models"])
    std::printf("                      %s\n", m.get<std::string>().c_str());
  std::printf("  bodies            : %zu rigid (%zu static), %zu soft\n",
              s["rigid_bodies"].get<std::size_t>(), s["static_bodies"].get<std::size_t>(),
              s["soft_bodies"].get<std::size_t>());
  std::printf("  collision shapes  : %zu mesh vertices, %zu primitives\n",
              s["collision_vertices"].get<std::size_t>(),
              s["collision_primitives"].get<std::size_t>());
  std::printf("  joints            : %zu (%zu take commands)\n", s["joints"].get<std::size_t>(),
              s["controllable_joints"].get<std::size_t>());
  std::printf("  articulations     : %zu in reduced coordinates\n",
              s["articulations"].get<std::size_t>());
  std::printf("  simulated         : %llu steps of %.3f ms = %.3f s\n",
              static_cast<unsigned long long>(s["steps"].get<std::uint64_t>()),
              s["step_size_s"].get<double>() * 1e3, s["sim_time_s"].get<double>());
  std::printf("  wall time         : %.3f s (real-time factor %.2fx)\n",
              s["wall_time_s"].get<double>(), s["real_time_factor"].get<double>());
  const auto& f = s["loop_frequency_hz"];
  std::printf("  dynamic loop      : %.0f Hz mean", f["mean"].get<double>());
  if (f["windows"].get<std::uint64_t>() > 0) {
    std::printf(" (1 s windows: %.0f .. %.0f Hz)", f["window_min"].get<double>(),
                f["window_max"].get<double>());
  }
  std::printf("\n  state             : %s\n", s["finite"].get<bool>()
                                                  ? "finite (no NaN)"
                                                  : "BLEW UP: stopped at the step that did");
  if (!s["failure"].is_null()) {
    std::printf("                      %s\n", s["failure"].get<std::string>().c_str());
  }
}

void addOptions(CLI::App& app, Options& o) {
  app.add_option("--launch_file", o.launch_file, "AMBF launch file")->check(CLI::ExistingFile);
  app.add_option("-l,--load_multibodies", o.launch_indices,
                 "indices of the launch file's multibody configs, e.g. 0,3 (default: all)");
  app.add_option("-a,--load_multibody_files", o.extra_files, "extra ADF/URDF files")
      ->delimiter(',');
  app.add_option("--world", o.world_file, "world file when no launch file is given")
      ->check(CLI::ExistingFile);
  app.add_option("-p,--phx_frequency", o.rate_hz, "dynamic loop rate in Hz")
      ->check(common::kFinitePositive);
  app.add_option("-t,--fixed_phx_timestep", o.fixed_time_step,
                 "advance exactly 1/p per iteration (false: follow the wall clock)");
  app.add_flag("--free-run", o.free_run, "do not pace the loop: run as fast as the CPU allows");
  app.add_option("-g,--show_gui", o.show_gui, "open a viewer window (AMBF's flag; also --gui)");
  app.add_flag("--gui", o.show_gui, "open a viewer window");
  app.add_option("--snapshot", o.snapshot,
                 "write a PNG of the scene at the end (with --snapshot-every: a numbered series); "
                 "headless: no display needed");
  common::addVideoFlags(app, o.video, "the run");
  app.add_option("--visual-skin", o.visual_skin,
                 "meshes drawn on bodies by name, e.g. raven_description/models/raven2/"
                 "ambf_visuals.yaml (AMBF's Raven-II meshes on our links)")
      ->check(CLI::ExistingFile);
  app.add_option("--snapshot-every", o.snapshot_every, "simulated seconds between snapshots")
      ->check(common::kFinitePositive);
  app.add_flag("--collision-view", o.collision_view,
               "show Bullet's collision shapes instead of the visuals (key C in the window)");
  app.add_flag("--contacts", o.contacts, "show contact points (key K in the window)");
  app.add_option("--steps", o.max_steps, "stop after this many internal steps");
  app.add_option("--duration", o.duration, "stop after this many simulated seconds")
      ->check(common::kFiniteNonNegative);
  app.add_option("--step-size", o.step_size, "fixed internal step in seconds")
      ->check(common::finiteWithin(1e-6, 0.1));
  app.add_flag("--strict", o.strict,
               "what AMBF tolerates (unknown keys, missing meshes or mass) is an error, not a "
               "warning");
  app.add_option("--summary-json", o.summary_json, "also write the exit summary as JSON");
  app.add_flag("-q,--quiet", o.quiet, "no once-a-second loop report");
}

/// The loop the options ask for, reporting once a second unless quiet.
std::unique_ptr<ambf_like::PhysicsLoop> makeLoop(ambf_like::World& world, const Options& o) {
  ambf_like::LoopOptions loop_options;
  loop_options.rate_hz = o.rate_hz;
  loop_options.paced = !o.free_run;
  loop_options.fixed_time_step = o.fixed_time_step || o.free_run;
  auto loop = std::make_unique<ambf_like::PhysicsLoop>(world, loop_options);
  if (const double asked = 1.0 / o.rate_hz / world.stepSize();
      asked > static_cast<double>(loop->stepsPerIteration()) + 0.5) {
    spdlog::warn(
        "a {} Hz loop asks for {:.0f} internal steps an iteration, more than the world's max "
        "iterations: each takes {}, as AMBF's does, and simulated time runs slower than the loop",
        o.rate_hz, asked, loop->stepsPerIteration());
  }
  if (!o.quiet) {
    loop->on_window = [&world](const ambf_like::FrequencyMeter& meter) {
      spdlog::info("Phx {:.0f} Hz   sim time {:.3f} s", meter.frequency(), world.time());
    };
  }
  return loop;
}

/// What watches the run: a viewer window or headless snapshots, and a video.
struct Watchers {
  std::unique_ptr<viewer::Viewer> view;
  std::optional<viewer::SnapshotSchedule> schedule;
  std::unique_ptr<viewer::VideoRecorder> video;
};

/// The watchers the options ask for; throws std::runtime_error naming the one that failed.
Watchers openWatchers(ambf_like::World& world, const Options& o) {
  Watchers w;
  if (o.show_gui || !o.snapshot.empty()) {
    viewer::ViewerOptions view_options;
    view_options.window = o.show_gui;
    view_options.view = {o.collision_view, o.contacts};
    view_options.visual_skin = o.visual_skin;
    view_options.title = "ambf_like " + (o.launch_file.empty() ? std::string() : o.launch_file);
    try {
      w.view = std::make_unique<viewer::Viewer>(world, view_options);
    } catch (const std::exception& e) {
      throw std::runtime_error(std::string("viewer: ") + e.what());
    }
    if (o.snapshot_every > 0.0) w.schedule.emplace(o.snapshot, o.snapshot_every);
  }
  if (!o.video.file.empty()) {
    try {
      viewer::VideoOptions video_options = viewer::VideoOptions::of(o.video);
      video_options.look = {o.collision_view, o.contacts};
      video_options.visual_skin = o.visual_skin;
      w.video = std::make_unique<viewer::VideoRecorder>(world, video_options, std::nullopt);
    } catch (const std::exception& e) {
      throw std::runtime_error(std::string("video: ") + e.what());
    }
  }
  return w;
}

/// How a run of the loop ended.
struct RunEnd {
  std::optional<std::string> diverged;  ///< the guard's reason, when the world blew up
  double wall = 0.0;                    ///< wall-clock seconds
};

/// Iterates the loop until the options' end, a signal or a closed window; throws for a snapshot
/// that cannot be written.
RunEnd run(ambf_like::PhysicsLoop& loop, ambf_like::World& world, Watchers& w, const Options& o) {
  std::signal(SIGINT, [](int) { g_stop = true; });
  std::signal(SIGTERM, [](int) { g_stop = true; });
  auto done = [&] {
    return g_stop || (w.view && w.view->closed()) ||
           (o.max_steps > 0 && world.stepCount() >= o.max_steps) ||
           (o.duration > 0.0 && world.time() + world.stepSize() / 2 >= o.duration);
  };
  const auto start = std::chrono::steady_clock::now();
  RunEnd end;
  try {
    while (!done()) {
      loop.iterate();
      if (w.video) w.video->capture(world);
      if (w.view) {
        w.view->publish(world);
        if (w.schedule) w.schedule->maybeTake(*w.view, world);
      }
    }
  } catch (const ambf_like::SimulationDiverged& e) {
    spdlog::error("{}", e.what());
    end.diverged = e.what();
  }
  end.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return end;
}

/// Finishes the video and takes the end's snapshot; throws naming what failed.
void closeWatchers(Watchers& w, ambf_like::World& world, const Options& o) {
  if (w.video) spdlog::info("video: {}", w.video->finish().describe());
  if (w.view && !o.snapshot.empty() && !w.schedule) {
    try {
      w.view->snapshot(world, o.snapshot);
    } catch (const std::exception& e) {
      throw std::runtime_error(std::string("snapshot: ") + e.what());
    }
    spdlog::info("snapshot: {}", o.snapshot);
  }
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  CLI::App app{
      "ambf_like: AMBF-style ADF/URDF models on a double-precision Bullet world, "
      "headless. With no model given it runs the bundled demo scene for 5 s."};
  addOptions(app, o);
  CLI11_PARSE(app, argc, argv);

  if (o.snapshot_every > 0.0 && o.snapshot.empty()) {
    spdlog::error("--snapshot-every needs --snapshot FILE.png to name the series");
    return 2;
  }
  if (o.launch_file.empty() && o.extra_files.empty()) {
    o.launch_file = AMBF_LIKE_DEFAULT_LAUNCH;
    if (o.max_steps == 0 && o.duration == 0.0) o.duration = 5.0;
    spdlog::info("no model given: running the bundled demo scene {}", o.launch_file);
  }

  try {
    const ambf_like::LoadedScene scene = load(o);
    for (const auto& warning : scene.warnings) spdlog::warn("{}", warning.str());
    ambf_like::WorldOptions world_options;
    world_options.step_size = o.step_size;
    ambf_like::MeshLibrary meshes;
    ambf_like::World world(scene.spec, meshes, world_options);
    for (const auto& warning : world.warnings()) spdlog::warn("{}", warning);
    const auto loop = makeLoop(world, o);
    Watchers watchers = openWatchers(world, o);
    const RunEnd end = run(*loop, world, watchers, o);
    closeWatchers(watchers, world, o);
    const auto summary = summarize(scene, world, loop->meter(), end.wall, end.diverged);
    printSummary(summary);
    if (!o.summary_json.empty()) std::ofstream(o.summary_json) << summary.dump(2) << "\n";
    return summary["finite"].get<bool>() ? 0 : 3;
  } catch (const std::exception& e) {
    spdlog::error("{}", e.what());
    return 1;
  }
}
