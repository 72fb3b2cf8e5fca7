// raven_calibrate: fits the twin's tracking response (command latency, and per drive a natural
// frequency and damping ratio) to physical replays of one recording's inputs, reports the twin's
// j_P and j_V before and after per joint, scores the fit on trials it was not fitted on
// (leave-one-out), and writes a calibration profile for --calibration.

#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <future>
#include <thread>

#include "analysis/metrics.hpp"
#include "calibration/calibration_file.hpp"
#include "calibration/replay_timing.hpp"
#include "calibration/tracking_fit.hpp"
#include "raven/control_cycle.hpp"
#include "recording/recording_io.hpp"

namespace {

using calibration::Figures;

/// Command-line settings.
struct Settings {
  std::filesystem::path ci;
  std::vector<std::filesystem::path> physical;
  std::filesystem::path out = "calibration.yaml";
  bool stand_in = false;
  bool paper_deadzone = false;
  std::string mapping = "m2";
  double rate = 500.0;
  int man_steps = 10;
  int max_evaluations = 200;
  int threads = 2;
  bool leave_one_out = true;
};

calibration::ReplaySetup replaySetup(const Settings& s) {
  calibration::ReplaySetup setup;
  setup.inputs = recording::readCi(s.ci);
  setup.controller.rate = s.rate;
  setup.controller.caps.min_steps = s.man_steps;
  setup.controller.scheme = controller::mappingSchemeNamed(s.mapping);
  setup.controller.mapping.deadzone_reads_y_twice = s.paper_deadzone;
  if (s.stand_in) setup.twin.stand_in = twin::CableActuationParams::physicalStandIn();
  return setup;
}

/// The physical trials named on the command line (files or directories; only the physical
/// platform's recordings are used, everything else is reported and left out).
std::vector<analysis::Trial> loadPhysical(const std::vector<std::filesystem::path>& inputs) {
  const auto set =
      analysis::loadTrials(inputs, analysis::readProfiles(analysis::defaultProfilesFile()));
  for (const auto& issue : set.issues) {
    spdlog::warn("{}: {}{}", issue.path.string(), issue.reason,
                 issue.excluded ? " (left out)" : "");
  }
  std::vector<analysis::Trial> trials;
  for (const auto& platform : set.platforms) {
    if (platform.profile.role == analysis::Role::Physical) {
      trials.insert(trials.end(), platform.trials.begin(), platform.trials.end());
    } else {
      for (const auto& t : platform.trials) {
        spdlog::warn("{}: a {} recording, not physical: left out", t.path.string(),
                     platform.profile.name);
      }
    }
  }
  return trials;
}

void printFigures(const char* label, const Figures& f) {
  std::printf("  %-34s %10.4f %10.3f %10.4f %10.3f\n", label, f.revolute_position,
              f.insertion_position, f.revolute_velocity, f.insertion_velocity);
}

void printFigureHeader() {
  std::printf("  %-34s %10s %10s %10s %10s\n", "", "rev j_P", "ins j_P", "rev j_V", "ins j_V");
  std::printf("  %-34s %10s %10s %10s %10s\n", "", "rad", "mm", "rad/s", "mm/s");
}

void printJoints(const calibration::JointFigures& before, const calibration::JointFigures& after,
                 const calibration::JointFigures& robot) {
  std::printf(
      "\nper joint, mean |difference| against the physical trials (T_PP: the robot's own)\n");
  std::printf("  %-16s %-6s %10s %10s %10s   %10s %10s %10s\n", "joint", "unit", "j_P before",
              "after", "T_PP", "j_V before", "after", "T_PP");
  const auto& joints = analysis::recordedJoints();
  for (std::size_t i = 0; i < joints.size(); ++i) {
    const bool mm = joints[i].unit == "m";
    std::printf("  %-16s %-6s %10.4f %10.4f %10.4f   %10.4f %10.4f %10.4f\n",
                joints[i].name.c_str(), mm ? "mm" : "rad", before.position[i], after.position[i],
                robot.position[i], before.velocity[i], after.velocity[i], robot.velocity[i]);
  }
}

/// One fit job: fit on `train`, score on `test` (may be empty).
struct Fold {
  std::string name;
  analysis::PlatformTrials train, test;
  calibration::FitResult fit;
  Figures held_out{}, held_out_before{};
};

int run(const Settings& s) {
  const auto started = std::chrono::steady_clock::now();
  calibration::ReplaySetup setup = replaySetup(s);
  const auto physical_list = loadPhysical(s.physical);
  if (physical_list.empty()) throw std::runtime_error("no physical trial to fit on");
  const auto physical = calibration::physicalTrials(physical_list);
  std::printf("raven_calibrate: %zu input rows (%s), %zu physical trial(s)%s\n",
              setup.inputs.size(), s.ci.c_str(), physical_list.size(),
              s.stand_in ? ", physical stand-in" : "");

  // The recording controller's timing first: the twin's rows are then as far apart as the
  // robot's, so its velocities can be compared.
  const auto shipped = calibration::replayOnTwin(setup, std::nullopt);
  setup.controller.iteration_overhead =
      calibration::measureIterationOverhead(shipped, physical_list);
  std::printf("iteration overhead of the recording controller (median, measured): %.2f ms\n",
              1e3 * setup.controller.iteration_overhead);
  const auto before = calibration::replayOnTwin(setup, std::nullopt);
  const Figures before_all = calibration::twinVsPhysical(before, physical);
  const Figures robot =
      physical_list.size() >= 2 ? calibration::robotRepeatability(physical) : before_all;
  auto scaleFor = [&](const analysis::PlatformTrials& train) {
    return train.trials.size() >= 2 ? calibration::robotRepeatability(train)
                                    : calibration::twinVsPhysical(before, train);
  };

  std::vector<Fold> folds;
  if (s.leave_one_out && physical_list.size() >= 2) {
    for (std::size_t k = 0; k < physical_list.size(); ++k) {
      Fold f;
      f.name = "without " + physical_list[k].path.filename().string();
      std::vector<analysis::Trial> train;
      for (std::size_t i = 0; i < physical_list.size(); ++i) {
        if (i != k) train.push_back(physical_list[i]);
      }
      f.train = calibration::physicalTrials(train);
      f.test = calibration::physicalTrials({physical_list[k]});
      folds.push_back(std::move(f));
    }
  }
  folds.push_back({"all trials", physical, {}, {}, {}, {}});

  calibration::FitOptions fit_options;
  fit_options.max_evaluations = s.max_evaluations;
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (std::size_t i = next++; i < folds.size(); i = next++) {
      Fold& f = folds[i];
      f.fit = calibration::fitTracking(
          setup, f.train, scaleFor(f.train), fit_options, [&](int n, double score) {
            if (n % 25 == 0) {
              std::fprintf(stderr, "  %s: %d replays, score %.4f\n", f.name.c_str(), n, score);
            }
          });
      if (!f.test.trials.empty()) {
        f.held_out =
            calibration::twinVsPhysical(calibration::replayOnTwin(setup, f.fit.tracking), f.test);
        f.held_out_before = calibration::twinVsPhysical(before, f.test);
      }
      std::fprintf(stderr, "  %s: score %.4f after %d replays (%s)\n", f.name.c_str(), f.fit.score,
                   f.fit.evaluations, f.fit.stop_reason.c_str());
    }
  };
  std::vector<std::thread> pool;
  for (int t = 0; t < std::max(1, s.threads); ++t) pool.emplace_back(worker);
  for (auto& t : pool) t.join();

  const Fold& final_fit = folds.back();
  const auto after = calibration::replayOnTwin(setup, final_fit.fit.tracking);
  const Figures after_all = calibration::twinVsPhysical(after, physical);

  std::printf("\nsummary figures, mean |difference| (rows aligned by index, no offsets removed)\n");
  printFigureHeader();
  if (physical_list.size() >= 2) printFigures("T_PP physical vs physical", robot);
  printFigures("T_PS twin as shipped vs physical", calibration::twinVsPhysical(shipped, physical));
  printFigures("T_PS + recording's timing", before_all);
  printFigures("T_PS + fitted response (after)", after_all);
  if (folds.size() > 1) {
    std::printf("\nleave-one-out: fitted without one trial, scored on it alone\n");
    printFigureHeader();
    Figures mean{};
    for (std::size_t i = 0; i + 1 < folds.size(); ++i) {
      const auto& f = folds[i];
      printFigures(("before, " + f.test.trials[0].path.filename().string()).c_str(),
                   f.held_out_before);
      printFigures(("after,  " + f.test.trials[0].path.filename().string()).c_str(), f.held_out);
      const auto v = f.held_out.values();
      const double n = static_cast<double>(folds.size() - 1);
      mean.revolute_position += v[0] / n;
      mean.insertion_position += v[1] / n;
      mean.revolute_velocity += v[2] / n;
      mean.insertion_velocity += v[3] / n;
    }
    printFigures("held-out mean", mean);
    std::printf("  leave-one-out score (held-out figures over T_PP, mean of four): %.3f\n",
                calibration::fidelityScore(mean, robot));
  }
  printJoints(calibration::jointsTwinVsPhysical(before, physical),
              calibration::jointsTwinVsPhysical(after, physical),
              physical_list.size() >= 2 ? calibration::jointsRepeatability(physical)
                                        : calibration::jointsTwinVsPhysical(before, physical));

  std::printf("\nfitted response (all trials): latency %.2f cycles\n",
              final_fit.fit.tracking.latency_cycles);
  const auto& parameters = calibration::trackingParameters();
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    std::printf("  %-28s %10.4f  (bounds %g..%g)\n", parameters[i].name.c_str(),
                final_fit.fit.values[i], parameters[i].lower, parameters[i].upper);
  }

  calibration::FitProvenance provenance;
  provenance.inputs = s.ci.string();
  for (const auto& t : physical_list) provenance.physical.push_back(t.path.string());
  provenance.notes.push_back(
      fmt::format("score {:.4f} (mean of the four figures over T_PP) after {} replays, {}",
                  final_fit.fit.score, final_fit.fit.evaluations, final_fit.fit.stop_reason));
  provenance.notes.push_back(fmt::format(
      "T_PS after: revolute j_P {:.4f} rad, insertion j_P {:.3f} mm, revolute j_V {:.4f} rad/s, "
      "insertion j_V {:.3f} mm/s",
      after_all.revolute_position, after_all.insertion_position, after_all.revolute_velocity,
      after_all.insertion_velocity));
  provenance.notes.push_back(std::string("replayed with ") +
                             (s.paper_deadzone ? "--paper-deadzone, " : "") + "--mapping " +
                             s.mapping + (s.stand_in ? ", --stand-in" : ""));
  calibration::writeCalibration(
      s.out, {final_fit.fit.tracking, setup.controller.iteration_overhead}, provenance);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  std::printf("\nwrote %s (%.0f s)\n", s.out.c_str(), seconds);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Fits the twin's tracking response to physical replays of one recording's gamepad inputs "
      "and writes a calibration profile (raven_controller/raven_twin_node --calibration)."};
  Settings s;
  app.add_option("--ci", s.ci, "the recorded controller inputs (ci file) the trials replayed")
      ->required()
      ->check(CLI::ExistingFile);
  app.add_option("physical", s.physical, "physical rs recordings, files or directories")
      ->required();
  app.add_option("--out", s.out, "calibration profile to write (YAML)");
  app.add_flag("--stand-in", s.stand_in, "fit the response in front of the physical stand-in");
  app.add_flag("--paper-deadzone", s.paper_deadzone,
               "replay with the released controller's deadzone test (the paper's recordings)");
  app.add_option("--mapping", s.mapping, "initial mapping of the replay: m2, m1-left, m1-right")
      ->check(CLI::IsMember({"m2", "m1-left", "m1-right"}));
  app.add_option("--rate", s.rate, "command steps per second of the replay")
      ->check(CLI::Range(1.0, raven::kControlRate));
  app.add_option("--man-steps", s.man_steps, "least steps per manual iteration")
      ->check(CLI::Range(1, 100));
  app.add_option("--max-evaluations", s.max_evaluations, "replays per fit at most")
      ->check(CLI::Range(10, 100000));
  app.add_option("--threads", s.threads, "fits run in parallel (one per core)")
      ->check(CLI::Range(1, 64));
  app.add_flag("!--no-leave-one-out", s.leave_one_out, "fit on every trial only");
  bool verbose = false;
  app.add_flag("-v,--verbose", verbose, "log every replay's mode changes");
  CLI11_PARSE(app, argc, argv);
  spdlog::set_level(verbose ? spdlog::level::info : spdlog::level::warn);
  try {
    return run(s);
  } catch (const std::exception& e) {
    spdlog::error("{}", e.what());
    return 1;
  }
}
