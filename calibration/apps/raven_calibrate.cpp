// raven_calibrate: fits the twin's actuation (the mechanics behind each motor) to physical
// recordings with a leave-one-out report (`fit`), scores a calibration by end-to-end replays of
// the recordings' inputs against the robot's own spread (`score`), and proposes the next
// excitation motion to record on the robot (`propose`).

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <optional>
#include <thread>

#include "analysis/error_windows.hpp"
#include "calibration/actuation_fit.hpp"
#include "calibration/command_delivery.hpp"
#include "calibration/excitation.hpp"
#include "calibration/replay_score.hpp"
#include "calibration/replay_timing.hpp"
#include "common/actuation_flag.hpp"
#include "common/number_checks.hpp"
#include "raven/control_cycle.hpp"
#include "recording/recording_io.hpp"
#include "twin/calibration_profile.hpp"

namespace {

using analysis::ActuatorSignal;

/// How the recordings' inputs were replayed (the controller's settings).
struct ReplayFlags {
  std::filesystem::path ci;
  bool paper_deadzone = false;
  std::string mapping = "m2";
  double rate = 500.0;
  int man_steps = 10;

  void add(CLI::App& app, bool ci_required) {
    auto* option =
        app.add_option("--ci", ci, "the recorded controller inputs (ci file) the trials replayed")
            ->check(CLI::ExistingFile);
    if (ci_required) option->required();
    app.add_flag("--paper-deadzone", paper_deadzone,
                 "replay with the released controller's deadzone test (the paper's recordings)");
    app.add_option("--mapping", mapping, "initial mapping of the replay: m2, m1-left, m1-right")
        ->check(CLI::IsMember({"m2", "m1-left", "m1-right"}));
    app.add_option("--rate", rate, "command steps per second of the replay")
        ->check(common::finiteWithin(1.0, raven::kControlRate));
    app.add_option("--man-steps", man_steps, "least steps per manual iteration")
        ->check(common::finiteWithin(1, 100));
  }
  calibration::ReplaySetup setup(double iteration_overhead) const {
    calibration::ReplaySetup s;
    if (!ci.empty()) s.inputs = recording::readCi(ci);
    s.controller.rate = rate;
    s.controller.caps.min_steps = man_steps;
    s.controller.scheme = controller::mappingSchemeNamed(mapping);
    s.controller.mapping.deadzone_reads_y_twice = paper_deadzone;
    s.controller.iteration_overhead = iteration_overhead;
    return s;
  }
};

/// The physical robot's trials among the files and directories named, as raven_analyze's
/// platform profiles assign them; every other file is reported and left out. Throws when a
/// physical trial logs no actuator signals or fewer than two remain.
std::vector<analysis::Trial> loadPhysical(const std::vector<std::filesystem::path>& inputs) {
  const auto set = analysis::loadTrials(
      inputs, analysis::readRecordingSources(analysis::defaultRecordingSourcesFile()));
  for (const auto& issue : set.issues) {
    spdlog::warn("{}: {}{}", issue.path.string(), issue.reason,
                 issue.excluded ? " (left out)" : "");
  }
  std::vector<analysis::Trial> trials;
  for (const auto& platform : set.platforms) {
    for (const auto& t : platform.trials) {
      if (platform.profile.role != analysis::Role::Physical) {
        spdlog::warn("{}: a {} recording, not physical: left out", t.path.string(),
                     platform.profile.name);
        continue;
      }
      if (!t.actuators) {
        throw std::runtime_error(t.path.string() +
                                 ": logs no finite motor signals (jpos_d, mpos, mvel, mpos_d, Tau, "
                                 "dac_vals in every row)");
      }
      trials.push_back(t);
    }
  }
  if (trials.size() < 2) {
    throw std::runtime_error(fmt::format(
        "{} physical recording(s) found: the robot's spread needs two or more", trials.size()));
  }
  return trials;
}

std::vector<analysis::ActuatorTrace> replayTraces(const calibration::ReplayScore& score) {
  std::vector<analysis::ActuatorTrace> t;
  for (const auto& rs : score.replays) t.push_back(analysis::actuatorTrace(rs));
  return t;
}

std::vector<analysis::ActuatorTrace> tracesOf(const std::vector<analysis::Trial>& trials) {
  std::vector<analysis::ActuatorTrace> t;
  for (const auto& trial : trials) t.push_back(*trial.actuators);
  return t;
}

void printActuators(const char* title, const analysis::ActuatorFidelity& f) {
  std::printf("\n%s: mean |twin - physical| over the robot's own spread (median over joints)\n",
              title);
  std::printf("  %-8s %7s |", "signal", "median");
  for (raven::Arm arm : raven::kArms) {
    for (auto name : raven::kJointNames)
      std::printf(" %c.%-6.6s", raven::armName(arm)[0], std::string(name).c_str());
  }
  std::printf("\n");
  for (std::size_t k = 0; k < analysis::kActuatorSignals.size(); ++k) {
    std::printf("  %-8s %6.2fx |", analysis::columnName(analysis::kActuatorSignals[k]),
                f.median_ratio[k]);
    for (std::size_t a = 0; a < 2; ++a) {
      for (int j = 0; j < raven::kJointCount; ++j)
        std::printf(" %8.2f", f.twin[k][a](j) / f.spread[k][a](j));
    }
    std::printf("\n");
  }
}

void printFigures(const calibration::ReplayScore& s) {
  std::printf(
      "\njoint figures, twin vs its own trial (mean |difference|) against T_PP (physical vs "
      "physical)\n");
  const auto& names = calibration::Figures::names();
  for (std::size_t k = 0; k < 2; ++k) {
    const auto t = s.twin[k].values();
    const auto r = s.robot[k].values();
    for (std::size_t i = 0; i < 4; ++i) {
      std::printf("  %-22s %-17s twin %9.4f   T_PP %9.4f   %s\n", names[i].c_str(),
                  k == 0 ? "as recorded" : "first row removed", t[i], r[i],
                  t[i] <= r[i] ? "within" : "OUTSIDE");
    }
  }
  std::printf("  %d of 8 joint figures within the robot's own repeatability\n", s.figuresWithin());
}

void printMechanics(const twin::CalibrationProfile& p) {
  std::printf("\nfitted mechanics (+- standard deviation)\n");
  for (raven::Arm arm : raven::kArms) {
    const auto a = raven::slot(arm);
    const twin::MotorMechanics &m = p.mechanics[a], &u = p.uncertainty[a];
    for (int v = 0; v < calibration::kMechanicsValues; ++v) {
      std::printf("  %-6s %-14s", std::string(raven::armName(arm)).c_str(),
                  std::string(twin::MotorMechanics::kNames[static_cast<std::size_t>(v)]).c_str());
      for (int j = 0; j < raven::kJointCount; ++j) {
        std::printf(" %9.3g+-%-8.2g", m.field(static_cast<std::size_t>(v))(j),
                    u.field(static_cast<std::size_t>(v))(j));
      }
      std::printf("\n");
    }
  }
}

/// The recordings' own setpoints through the motor model with `mechanics`, against them.
analysis::ActuatorFidelity setpointFidelity(const std::vector<analysis::ActuatorTrace>& traces,
                                            const twin::ArmsMechanics& mechanics) {
  std::vector<analysis::ActuatorTrace> replays;
  for (const auto& t : traces) replays.push_back(calibration::replaySetpoints(t, mechanics));
  return analysis::actuatorFidelity(replays, traces);
}

/// "median ratio mpos 0.16, mvel 0.88, Tau 1.64, dac_vals 1.64" for the profile's notes.
std::string medianRatios(const analysis::ActuatorFidelity& f) {
  std::string line = "median ratio";
  for (std::size_t k = 0; k < analysis::kActuatorSignals.size(); ++k) {
    line += fmt::format("{} {} {:.2f}", k ? "," : "",
                        analysis::columnName(analysis::kActuatorSignals[k]), f.median_ratio[k]);
  }
  return line;
}

/// One leave-one-out fold's result.
struct Fold {
  std::size_t held_out = 0;
  calibration::ActuationFitResult fit;
  analysis::ActuatorFidelity held_out_score;
};

struct FitSettings {
  std::vector<std::filesystem::path> physical;
  ReplayFlags replay;
  std::filesystem::path out = "raven2_calibration.yaml";
  int evaluations = 100;
  int threads = 2;
  bool leave_one_out = true;
  std::filesystem::path from;       ///< a profile to start from, or the catalogue values
  std::vector<std::string> fields;  ///< the MotorMechanics fields fitted; empty: all
};

/// Where a fit starts: `from`'s mechanics, or catalogue inertias and raven2_sim's friction.
twin::ArmsMechanics fitStart(const FitSettings& s) {
  if (s.from.empty()) return calibration::startingMechanics();
  return twin::CalibrationProfile::load(s.from).mechanics;
}

/// The indices (MotorMechanics::kNames) of the fields named.
std::vector<std::size_t> fieldIndices(const std::vector<std::string>& names) {
  std::vector<std::size_t> indices;
  for (const auto& name : names) {
    const auto& all = twin::MotorMechanics::kNames;
    indices.push_back(
        static_cast<std::size_t>(std::find(all.begin(), all.end(), name) - all.begin()));
  }
  return indices;
}

int runFit(const FitSettings& s) {
  const auto started = std::chrono::steady_clock::now();
  const auto physical = loadPhysical(s.physical);
  const auto traces = tracesOf(physical);
  std::printf("raven_calibrate fit: %zu physical trial(s)\n", physical.size());
  const twin::ArmsMechanics start = fitStart(s);
  printActuators(s.from.empty() ? "setpoint replays with the starting values (raven2_sim's "
                                  "friction, catalogue inertias)"
                                : "setpoint replays with the profile the fit starts from",
                 setpointFidelity(traces, start));

  // Folds: each trial held out (fitted on the others), then every trial.
  std::vector<Fold> folds;
  if (s.leave_one_out && traces.size() >= 3) {
    for (std::size_t k = 0; k < traces.size(); ++k) folds.push_back({k, {}, {}});
  }
  folds.push_back({traces.size(), {}, {}});
  calibration::ActuationFitOptions options;
  options.evaluations_per_joint = s.evaluations;
  options.fields = fieldIndices(s.fields);
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (std::size_t i = next++; i < folds.size(); i = next++) {
      Fold& f = folds[i];
      std::vector<analysis::ActuatorTrace> train;
      for (std::size_t k = 0; k < traces.size(); ++k) {
        if (k != f.held_out) train.push_back(traces[k]);
      }
      f.fit = calibration::fitActuation(train, start, options);
      if (f.held_out < traces.size()) {
        const auto& test = traces[f.held_out];
        f.held_out_score = analysis::actuatorFidelity(
            {calibration::replaySetpoints(test, f.fit.mechanics)}, {test}, train);
      }
      std::fprintf(stderr, "  fit %s: %d replays, score %.3f\n",
                   f.held_out < traces.size() ? ("without " + traces[f.held_out].name).c_str()
                                              : "on every trial",
                   f.fit.evaluations, f.fit.score.total());
    }
  };
  std::vector<std::thread> pool;
  for (int t = 0; t < std::max(1, s.threads); ++t) pool.emplace_back(worker);
  for (auto& t : pool) t.join();

  for (const Fold& f : folds) {
    if (f.held_out >= traces.size()) continue;
    printActuators(
        ("held out " + traces[f.held_out].name + " (fitted on the others, over their spread)")
            .c_str(),
        f.held_out_score);
  }

  twin::CalibrationProfile profile;
  profile.mechanics = folds.back().fit.mechanics;
  calibration::MechanicsInformation information = calibration::MechanicsInformation::none();
  for (const auto& t : traces) information += calibration::informationOf(profile.mechanics, t);
  profile.uncertainty = information.standardDeviations();
  const auto fitted = setpointFidelity(traces, profile.mechanics);
  printActuators("setpoint replays, fitted on every trial", fitted);
  printMechanics(profile);

  twin::FitProvenance provenance;
  for (const auto& t : physical) provenance.physical.push_back(t.path.string());
  provenance.notes.push_back("setpoint replays, fitted on every trial: " + medianRatios(fitted));
  if (!s.replay.ci.empty()) {
    // The recording controller's timing, then the whole chain from each trial's start.
    calibration::ReplaySetup setup = s.replay.setup(0.0);
    profile.applyTo(setup.twin);  // every increment delivered, for now
    const auto fast = calibration::replayOnTwin(setup);
    profile.iteration_overhead = calibration::measureIterationOverhead(fast, physical);
    setup.controller.iteration_overhead = profile.iteration_overhead;
    std::printf("\niteration overhead of the recording controller (median, measured): %.2f ms\n",
                1e3 * profile.iteration_overhead);
    // Every increment delivered first; the robot's own setpoints then say how many arrived.
    const auto delivered_all = calibration::scoreReplays(setup, physical);
    profile.servo_jr_delivered =
        calibration::measureServoDelivery(replayTraces(delivered_all), traces);
    profile.applyTo(setup.twin);
    std::printf("servo_jr increments the robot received (median share, measured): %.4f\n",
                profile.servo_jr_delivered);
    const auto score = calibration::scoreReplays(setup, physical);
    printActuators("end-to-end replays of the inputs, each from its trial's start",
                   score.actuators);
    printFigures(score);
    provenance.inputs = s.replay.ci.string();
    provenance.notes.push_back(
        fmt::format("end-to-end replays: {}; {} of 8 joint figures within T_PP",
                    medianRatios(score.actuators), score.figuresWithin()));
  }
  profile.save(s.out, provenance);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  std::printf("\nwrote %s (%.0f s)\n", s.out.c_str(), seconds);
  return 0;
}

/// One motor as the score's table names it: "r.jaw1", "right.jaw1", "l.elbow".
struct MotorName {
  raven::Arm arm = raven::Arm::Left;
  int joint = 0;
};

std::optional<MotorName> motorNamed(const std::string& text) {
  const auto dot = text.find('.');
  if (dot == std::string::npos) return std::nullopt;
  const std::string arm = text.substr(0, dot), joint = text.substr(dot + 1);
  const auto named = std::find_if(raven::kArms.begin(), raven::kArms.end(), [&](raven::Arm a) {
    return arm == raven::armName(a) || arm == raven::armName(a).substr(0, 1);  // as printed
  });
  if (named == raven::kArms.end()) return std::nullopt;
  MotorName m;
  m.arm = *named;
  const auto& names = raven::kJointNames;
  const auto it = std::find(names.begin(), names.end(), joint);
  if (it == names.end()) return std::nullopt;
  m.joint = static_cast<int>(it - names.begin());
  return m;
}

std::string motorNames() {
  std::string all;
  for (auto name : raven::kJointNames) all += (all.empty() ? "" : ", ") + std::string(name);
  return all;
}

struct ScoreSettings {
  std::vector<std::filesystem::path> physical;
  ReplayFlags replay;
  std::filesystem::path calibration;
  common::ActuationKind actuation = common::ActuationKind::Motors;
  std::filesystem::path write;  ///< directory for the twin's replays, or none
  std::string where;            ///< a motor whose difference is shown window by window, or none
  std::string where_signal = "Tau";  ///< its recorder column name
};

/// Where in the trials the motor's difference sits, 100 rows at a time.
void printWhere(const ScoreSettings& s, const calibration::ReplayScore& score,
                const std::vector<analysis::Trial>& physical) {
  const MotorName motor = *motorNamed(s.where);
  const auto signal =
      *std::find_if(analysis::kActuatorSignals.begin(), analysis::kActuatorSignals.end(),
                    [&](ActuatorSignal a) { return s.where_signal == analysis::columnName(a); });
  const auto twin = replayTraces(score);
  const auto robot = tracesOf(physical);
  constexpr std::size_t kRows = 100;
  const auto windows = analysis::errorWindows(twin, robot, signal, motor.arm, motor.joint, kRows);
  const auto k = static_cast<std::size_t>(signal);
  const double spread = score.actuators.spread[k][raven::slot(motor.arm)](motor.joint);
  std::printf(
      "\nwhere the %s arm's %s differs in %s (rows paired as scored, %zu at a time; "
      "times of %s)\n",
      std::string(raven::armName(motor.arm)).c_str(),
      std::string(raven::kJointNames[static_cast<std::size_t>(motor.joint)]).c_str(),
      analysis::columnName(signal), kRows, robot.front().name.c_str());
  for (const auto& w : windows) {
    std::printf(
        "  rows %4zu-%4zu  %6.1f-%6.1f s  %5.1f %% of it  mean %.4g %s (%.2fx the "
        "spread)\n",
        w.first_row, w.last_row, w.start, w.end, 100.0 * w.share, w.mean,
        analysis::loggedUnit(signal), spread > 0.0 ? w.mean / spread : 0.0);
  }
}

int runScore(const ScoreSettings& s) {
  const auto physical = loadPhysical(s.physical);
  const twin::CalibrationProfile profile = s.calibration.empty()
                                               ? twin::CalibrationProfile::shipped()
                                               : twin::CalibrationProfile::load(s.calibration);
  calibration::ReplaySetup setup = s.replay.setup(profile.iteration_overhead);
  const bool motors = s.actuation == common::ActuationKind::Motors;
  if (motors) profile.applyTo(setup.twin);
  std::printf("raven_calibrate score: %zu physical trial(s), %s, %s\n", physical.size(),
              motors ? "motor-level actuation" : "ideal servos",
              s.calibration.empty() ? twin::CalibrationProfile::shippedFile().c_str()
                                    : s.calibration.c_str());
  const auto score = calibration::scoreReplays(setup, physical);
  printActuators("end-to-end replays of the inputs, each from its trial's start", score.actuators);
  printFigures(score);
  if (!s.where.empty()) printWhere(s, score, physical);
  if (!s.write.empty()) {
    std::filesystem::create_directories(s.write);
    for (std::size_t k = 0; k < score.replays.size(); ++k) {
      // Named for raven_analyze's twin profile, one per physical trial, in its order.
      recording::RsWriter writer(s.write / fmt::format("twin_replay_{}.csv", k + 1));
      for (const auto& row : score.replays[k].rows) writer.writeRow(row);
    }
    std::printf("\nthe twin's replays: %s (raven_analyze %s PHYSICAL... compares them)\n",
                s.write.c_str(), s.write.c_str());
  }
  return 0;
}

struct ProposeSettings {
  std::filesystem::path calibration;
  std::filesystem::path out = "excitation_ci.csv";
  int candidates = 8;
  double seconds = 20.0;
  unsigned seed = 1;
};

int runPropose(const ProposeSettings& s) {
  const twin::CalibrationProfile profile = s.calibration.empty()
                                               ? twin::CalibrationProfile::shipped()
                                               : twin::CalibrationProfile::load(s.calibration);
  twin::CalibrationProfile profile_with_prior = profile;
  bool broad = true;
  for (const auto& arm : profile.uncertainty) {
    for (std::size_t k = 0; k < twin::MotorMechanics::kNames.size(); ++k)
      broad = broad && arm.field(k).isZero();
  }
  if (broad) {
    profile_with_prior.uncertainty = calibration::broadUncertainty(profile.mechanics);
    std::printf("the profile has no uncertainty: a broad prior (half of each value) is assumed\n");
  }
  const auto prior =
      calibration::MechanicsInformation::fromUncertainty(profile_with_prior.uncertainty);
  calibration::ReplaySetup setup = ReplayFlags{}.setup(profile.iteration_overhead);
  std::mt19937_64 random(s.seed);
  std::vector<calibration::Candidate> candidates;
  for (int i = 0; i < s.candidates; ++i) {
    candidates.push_back(
        calibration::scoreCandidate(setup, profile_with_prior, prior,
                                    calibration::randomExcitation(random, {s.seconds, 0.022})));
    const auto& c = candidates.back();
    std::printf("  candidate %d: expected reduction %5.1f %% %s\n", i + 1,
                100.0 * calibration::meanReduction(profile_with_prior.uncertainty,
                                                   calibration::expectedUncertainty(prior, c)),
                c.within_limits ? "" : "(comes within 1 % of a joint limit: left out)");
  }
  const calibration::Candidate* best = nullptr;
  for (const auto& c : candidates) {
    if (c.within_limits && (!best || c.log_det > best->log_det)) best = &c;
  }
  if (!best)
    throw std::runtime_error("every candidate came near a joint limit; try shorter --seconds");
  recording::CiWriter writer(s.out);
  for (const auto& pad : best->inputs) writer.write(pad);
  const auto after = calibration::expectedUncertainty(prior, *best);
  std::printf(
      "\nwrote %s: %zu rows, %.0f s; replay it on the robot with raven_controller --replay-ci, "
      "then fit with the new recording added\n",
      s.out.c_str(), best->inputs.size(), s.seconds);
  std::printf(
      "expected reduction of the fitted values' standard deviations: %.1f %% (mean over %s "
      "values)\n",
      100.0 * calibration::meanReduction(profile_with_prior.uncertainty, after), "the fitted");
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Fits the twin's motor-level actuation to physical recordings, scores it, and proposes "
      "the next excitation motion to record."};
  app.require_subcommand(1);
  bool verbose = false;
  app.add_flag("-v,--verbose", verbose, "log every replay's mode changes");

  FitSettings fit;
  auto* fit_cmd =
      app.add_subcommand("fit", "fit the mechanics behind each motor (leave-one-out reported)");
  fit_cmd
      ->add_option("physical", fit.physical,
                   "physical rs recordings of one motion, files or directories")
      ->required();
  fit.replay.add(*fit_cmd, false);
  fit_cmd->add_option("--out", fit.out, "calibration profile to write (YAML)");
  fit_cmd->add_option("--evaluations", fit.evaluations, "model replays per motor and sweep")
      ->check(common::finiteWithin(5, 10000));
  fit_cmd->add_option("--threads", fit.threads, "fits run in parallel")
      ->check(common::finiteWithin(1, 64));
  fit_cmd->add_flag("!--no-leave-one-out", fit.leave_one_out, "fit on every trial only");
  fit_cmd->add_option("--from", fit.from, "profile to start from (default: catalogue values)")
      ->check(CLI::ExistingFile);
  fit_cmd
      ->add_option("--fields", fit.fields,
                   "mechanics fitted, the others kept as they start (default: all)")
      ->check(CLI::IsMember(std::vector<std::string>(twin::MotorMechanics::kNames.begin(),
                                                     twin::MotorMechanics::kNames.end())));

  ScoreSettings score;
  auto* score_cmd = app.add_subcommand(
      "score", "replay the inputs on the twin from each trial's start and compare");
  score_cmd->add_option("physical", score.physical, "physical rs recordings, files or directories")
      ->required();
  score.replay.add(*score_cmd, true);
  score_cmd
      ->add_option("--calibration", score.calibration,
                   "profile to score (default: the shipped one)")
      ->check(CLI::ExistingFile);
  common::addActuationFlag(*score_cmd, score.actuation);
  score_cmd->add_option("--write", score.write,
                        "directory to write the twin's replays to (rs files)");
  score_cmd
      ->add_option("--where", score.where,
                   "a motor (l.jaw1, right.elbow, ...) whose difference is shown 100 rows at a "
                   "time: where in the trials it sits")
      ->check(CLI::Validator(
          [](std::string& text) {
            return motorNamed(text) ? std::string()
                                    : "a motor is l. or r. (left., right.) and one of " +
                                          motorNames() + ", not '" + text + "'";
          },
          "ARM.JOINT"));
  score_cmd
      ->add_option("--where-signal", score.where_signal, "the signal --where shows (default Tau)")
      ->check(CLI::IsMember({"mpos", "mvel", "Tau", "dac_vals"}));

  ProposeSettings propose;
  auto* propose_cmd = app.add_subcommand(
      "propose", "write the excitation motion that most reduces the fit's uncertainty");
  propose_cmd
      ->add_option("--calibration", propose.calibration,
                   "profile with its uncertainty (default: the shipped one)")
      ->check(CLI::ExistingFile);
  propose_cmd->add_option("--out", propose.out, "ci file to write");
  propose_cmd->add_option("--candidates", propose.candidates, "random candidates scored")
      ->check(common::finiteWithin(1, 1000));
  propose_cmd->add_option("--seconds", propose.seconds, "length of the motion")
      ->check(common::finiteWithin(2.0, 600.0));
  propose_cmd->add_option("--seed", propose.seed, "seed of the candidates");

  CLI11_PARSE(app, argc, argv);
  spdlog::set_level(verbose ? spdlog::level::info : spdlog::level::warn);
  try {
    if (*fit_cmd) return runFit(fit);
    if (*score_cmd) return runScore(score);
    return runPropose(propose);
  } catch (const std::exception& e) {
    spdlog::error("{}", e.what());
    return 1;
  }
}
