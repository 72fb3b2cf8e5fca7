// raven_calibrate's parts: the recording controller's measured timing, the actuation fit and its
// uncertainty, the profile it writes, and the shipped calibration of the paper's 2arm set, which
// must put the twin's joints within the robot's own repeatability and its actuator signals
// (mpos, mvel, Tau, dac_vals) within twice the robot's own spread.

#include <gtest/gtest.h>
#include <spdlog/spdlog.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <random>

#include "calibration/actuation_fit.hpp"
#include "calibration/excitation.hpp"
#include "calibration/mechanics_information.hpp"
#include "calibration/replay_score.hpp"
#include "calibration/replay_timing.hpp"
#include "common/load_error.hpp"
#include "test_files.hpp"
#include "twin/calibration_profile.hpp"

namespace {

analysis::Trial trialWithTimes(std::vector<double> times) {
  analysis::Trial t;
  t.time = std::move(times);
  t.position.resize(t.time.size());
  t.velocity.resize(t.time.size());
  return t;
}

TEST(ReplayTiming, TheOverheadIsTheMedianExtraTimePerRow) {
  // The twin: 10 and 12 steps of 2 ms. The robot: the same plus 1 ms, and one long pause.
  const auto twin = trialWithTimes({0.0, 0.020, 0.044, 0.064, 0.084});
  const auto robot = trialWithTimes({0.0, 0.021, 0.046, 0.067, 0.250});
  EXPECT_NEAR(calibration::measureIterationOverhead(twin, {robot}), 0.001, 1e-12);
  EXPECT_EQ(calibration::measureIterationOverhead(twin, {twin}), 0.0);
  EXPECT_EQ(calibration::measureIterationOverhead(twin, {}), 0.0);
}

/// The paper's 2arm set: its inputs, the released controller's deadzone, the physical trials.
struct Paper2arm {
  calibration::ReplaySetup setup;
  std::vector<analysis::Trial> physical;  ///< with their actuator signals
  std::vector<analysis::ActuatorTrace> traces() const {
    std::vector<analysis::ActuatorTrace> t;
    for (const auto& trial : physical) t.push_back(trial.actuators.value());
    return t;
  }
};

std::optional<Paper2arm> paper2arm() {
  const auto shared = test_support::sharedDataDir();
  if (shared.empty()) return std::nullopt;
  const auto dir = shared / "recordings/paper_2arm";
  Paper2arm p;
  p.setup.inputs = recording::readCi(dir / "2arm_ci.csv");
  p.setup.controller.mapping.deadzone_reads_y_twice = true;
  std::vector<std::filesystem::path> files;
  for (int k = 1; k <= 3; ++k)
    files.push_back(dir / ("2arm_physical_" + std::to_string(k) + ".csv"));
  const auto set = analysis::loadTrials(
      files, analysis::readRecordingSources(analysis::defaultRecordingSourcesFile()));
  p.physical = set.find("physical")->trials;
  return p;
}

twin::ArmsMechanics filled(double value) {
  twin::MotorMechanics m;
  for (std::size_t k = 0; k < twin::MotorMechanics::kNames.size(); ++k)
    m.field(k).setConstant(value);
  return {m, m};
}

TEST(CalibrationFile, WhatIsWrittenIsReadBack) {
  test_support::TempDir dir;
  twin::CalibrationProfile profile;
  profile.mechanics = calibration::startingMechanics();
  profile.mechanics[1].coulomb(raven::kJaw2) = 0.0123;
  profile.mechanics[0].gravity_error(raven::kElbow) = -0.25;
  profile.mechanics[1].load_friction(raven::kShoulder) = 0.3;
  profile.mechanics[0].offset(raven::kElbow) = -0.07;
  profile.uncertainty = filled(1e-4);
  profile.iteration_overhead = 0.001;
  profile.save(dir.path() / "c.yaml", {"inputs_ci.csv", {"a_physical_1.csv"}, {"a note"}});
  const auto read = twin::CalibrationProfile::load(dir.path() / "c.yaml");
  for (std::size_t a = 0; a < 2; ++a) {
    for (std::size_t k = 0; k < twin::MotorMechanics::kNames.size(); ++k) {
      EXPECT_LT((read.mechanics[a].field(k) - profile.mechanics[a].field(k)).cwiseAbs().maxCoeff(),
                1e-5 * (1.0 + profile.mechanics[a].field(k).cwiseAbs().maxCoeff()))
          << twin::MotorMechanics::kNames[k];
      EXPECT_TRUE(read.uncertainty[a].field(k).isApprox(profile.uncertainty[a].field(k), 1e-5));
    }
  }
  EXPECT_EQ(read.iteration_overhead, 0.001);
}

TEST(CalibrationFile, BadValuesAreRefusedNamingFileAndKey) {
  test_support::TempDir dir;
  twin::CalibrationProfile profile;
  profile.mechanics = calibration::startingMechanics();
  profile.uncertainty = filled(0.0);
  profile.save(dir.path() / "good.yaml", {});
  std::ifstream in(dir.path() / "good.yaml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto refused = [&](const std::string& from, const std::string& to, const std::string& named) {
    std::string bad = text;
    const auto at = bad.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    bad.replace(at, from.size(), to);
    std::ofstream(dir.path() / "bad.yaml") << bad;
    try {
      twin::CalibrationProfile::load(dir.path() / "bad.yaml");
      ADD_FAILURE() << "loaded with " << to;
    } catch (const common::LoadError& e) {
      EXPECT_NE(std::string(e.what()).find("bad.yaml"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(named), std::string::npos) << e.what();
    }
  };
  refused("inertia: [", "inertia: [-1, ", "inertia");
  refused("coulomb:", "friction:", "friction");
  refused("right:", "middle:", "middle");
  refused("offset: [0", "offset: [.nan", "offset");
}

TEST(CalibrationFile, AProfileWrittenBeforeTheOffsetWasFittedHasNone) {
  test_support::TempDir dir;
  twin::CalibrationProfile profile;
  profile.mechanics = calibration::startingMechanics();
  profile.mechanics[0].offset.setConstant(0.01);
  profile.mechanics[1].offset.setConstant(0.01);
  profile.uncertainty = filled(0.0);
  profile.save(dir.path() / "c.yaml", {});
  std::ifstream in(dir.path() / "c.yaml");
  std::string older;
  for (std::string line; std::getline(in, line);) {
    if (line.find("offset:") == std::string::npos) older += line + "\n";
  }
  std::ofstream(dir.path() / "older.yaml") << older;
  const auto read = twin::CalibrationProfile::load(dir.path() / "older.yaml");
  for (std::size_t a = 0; a < 2; ++a) {
    EXPECT_TRUE(read.mechanics[a].offset.isZero());
    EXPECT_TRUE(read.mechanics[a].coulomb.isApprox(profile.mechanics[a].coulomb, 1e-5));
  }
}

/// A recording that moves only the left shoulder, its setpoints as the robot would log them;
/// the left jaws are held at `left_jaws` each.
analysis::ActuatorTrace shoulderSweep(double left_jaws = M_PI / 4) {
  analysis::ActuatorTrace trace;
  const auto drive = twin::DriveTrain::raven2();
  raven::ArmJoints home;
  home << M_PI / 6, M_PI / 2, 0.4, 0.0, 0.0, M_PI / 4, M_PI / 4;
  for (int r = 0; r < 300; ++r) {
    const double t = 0.02 * r;
    raven::ArmJoints q = home;
    q(raven::kShoulder) += 0.05 * std::sin(2.0 * M_PI * 0.5 * t);
    q(raven::kJaw1) = q(raven::kJaw2) = left_jaws;
    trace.time.push_back(t);
    for (raven::Arm arm : raven::kArms) {
      auto& a = trace.arms[raven::slot(arm)];
      const raven::ArmJoints set = arm == raven::Arm::Left ? q : home;
      const raven::ArmJoints motor = drive.toMotor(arm, set);
      const raven::ArmJoints zero = raven::ArmJoints::Zero();
      a.push_back({set, set, motor, zero, motor, zero, zero});
    }
  }
  return trace;
}

TEST(Information, GrowsWithRecordingsAndIsNilForAMotorThatNeverMoves) {
  const auto trace = shoulderSweep();
  const auto mechanics = calibration::startingMechanics();
  const auto one = calibration::informationOf(mechanics, trace);
  auto two = one;
  two += one;
  const auto sd_one = one.standardDeviations();
  const auto sd_two = two.standardDeviations();
  EXPECT_GT(sd_one[0].coulomb(raven::kShoulder), 0.0);
  EXPECT_NEAR(sd_two[0].coulomb(raven::kShoulder),
              sd_one[0].coulomb(raven::kShoulder) / std::sqrt(2.0),
              1e-9 + 1e-6 * sd_one[0].coulomb(raven::kShoulder));
  // The right shoulder held still against friction: its Coulomb friction changes nothing.
  EXPECT_LT(one.blocks[1][raven::kShoulder](1, 1), 1e-6 * one.blocks[0][raven::kShoulder](1, 1));
}

// Every value a motor has is covered, and none it has not: the left jaws commanded past where
// they meet (their faces then set where they stop), the shoulder lifting the arm's weight.
TEST(Information, CoversEveryValueAMotorHasAndNoOther) {
  const auto sd = calibration::informationOf(calibration::startingMechanics(), shoulderSweep(-0.05))
                      .standardDeviations();
  const twin::MotorMechanics& left = sd[0];
  EXPECT_GT(left.gravity_error(raven::kShoulder), 0.0);
  EXPECT_GT(left.viscous(raven::kShoulder), 0.0);
  EXPECT_GT(left.offset(raven::kShoulder), 0.0);
  EXPECT_GT(left.face(raven::kJaw1), 0.0);
  EXPECT_GT(left.face(raven::kJaw2), 0.0);
  EXPECT_EQ(left.face(raven::kShoulder), 0.0);
  EXPECT_EQ(left.face(raven::kRoll), 0.0);
  EXPECT_EQ(left.gravity_error(raven::kJaw1), 0.0);
  EXPECT_GT(left.cable_friction(raven::kShoulder), 0.0);
  EXPECT_GT(left.cable_travel(raven::kShoulder), 0.0);
  EXPECT_EQ(left.cable_friction(raven::kJaw1), 0.0);
  EXPECT_EQ(left.cable_travel(raven::kRoll), 0.0);
}

TEST(ActuationFit, AShortFitImprovesOnItsStartingPoint) {
  auto paper = paper2arm();
  if (!paper) GTEST_SKIP() << "../shared/data is absent: the paper's recordings are needed";
  const auto traces = paper->traces();
  const auto spread = analysis::actuatorFidelity({traces[0]}, traces);
  const auto start = calibration::startingMechanics();
  const double before = calibration::scoreMechanics(start, traces, spread).total();
  calibration::ActuationFitOptions options;
  options.evaluations_per_joint = 6;
  options.sweeps = 1;
  const auto fit = calibration::fitActuation(traces, start, options);
  EXPECT_LT(fit.score.total(), before);
  for (const auto& m : fit.mechanics) EXPECT_TRUE(m.invalidReason().empty()) << m.invalidReason();
}

TEST(ShippedCalibration, AReplayStartedFromATrialBeginsWhereItBegan) {
  auto paper = paper2arm();
  if (!paper) GTEST_SKIP() << "../shared/data is absent: the paper's recordings are needed";
  const auto profile = twin::CalibrationProfile::shipped();
  profile.applyTo(paper->setup.twin);
  const auto physical = paper->physical[1].actuators.value();
  paper->setup.start = calibration::traceStart(physical);
  const auto replay = analysis::actuatorTrace(calibration::recordReplay(paper->setup));
  // Row 0 comes after the replay's 1 s wait, as the robot's came 1.4 s before its first input:
  // the motors held by friction, the tools' integrators a second further on.
  for (std::size_t a = 0; a < 2; ++a) {
    const auto& t = replay.arms[a].front();
    const auto& p = physical.arms[a].front();
    const double count = 2.0 * M_PI / 4000.0;  // rad
    EXPECT_LT((t.motor - p.motor).cwiseAbs().maxCoeff(), 2 * count) << "two counts";
    EXPECT_LT((t.torque - p.torque).cwiseAbs().maxCoeff(), 0.01) << "N m";
    EXPECT_LT((t.joint_setpoint - p.joint_setpoint).cwiseAbs().maxCoeff(), 1e-6);
  }
}

/// Per arm: roll, wrist and jaw1 - jaw2 of a setpoint.
Eigen::Vector3d heldValues(const raven::ArmJoints& q) {
  return {q(raven::kRoll), q(raven::kWrist), q(raven::kJaw1) - q(raven::kJaw2)};
}

TEST(ShippedCalibration, AReplayMakesTheFirstMoveTheRobotsControllerMade) {
  auto paper = paper2arm();
  if (!paper) GTEST_SKIP() << "../shared/data is absent: the paper's recordings are needed";
  const auto profile = twin::CalibrationProfile::shipped();
  profile.applyTo(paper->setup.twin);
  const auto score = calibration::scoreReplays(paper->setup, paper->physical);
  const double lost = 1.0 - profile.servo_jr_delivered;  // the twin's share of each increment
  double worst_held = 0.0, unheld = 0.0, worst_grasp = 0.0;
  for (std::size_t t = 0; t < paper->physical.size(); ++t) {
    const auto& robot = paper->physical[t].actuators.value();
    const auto twin = analysis::actuatorTrace(score.replays[t]);
    for (std::size_t a = 0; a < 2; ++a) {
      const raven::ArmJoints& start = robot.arms[a].front().joint_setpoint;
      // Under M2 nothing moves roll, wrist and jaw difference after the first move: the
      // twin's stay on the robot's to within the increments the robot lost.
      for (std::size_t r = 2; r < std::min(robot.rows(), twin.rows()); ++r) {
        const Eigen::Vector3d robot_held = heldValues(robot.arms[a][r].joint_setpoint);
        worst_held = std::max(
            worst_held,
            (heldValues(twin.arms[a][r].joint_setpoint) - robot_held).cwiseAbs().maxCoeff());
        unheld = std::max(unheld, (heldValues(start) - robot_held).cwiseAbs().maxCoeff());
      }
      // The jaws' sum once the first move is delivered: the robot's, less the share of it
      // the twin loses.
      const auto sum = [](const raven::ArmJoints& q) { return q(raven::kJaw1) + q(raven::kJaw2); };
      const double robot_sum = sum(robot.arms[a][10].joint_setpoint);
      const double moved = std::abs(robot_sum - sum(start));
      worst_grasp = std::max(
          worst_grasp, std::abs(sum(twin.arms[a][10].joint_setpoint) - robot_sum) - lost * moved);
    }
  }
  EXPECT_LT(worst_held, 1e-3) << "rad";
  EXPECT_GT(unheld, 0.05) << "rad: the robot's controller held values its first row does not show";
  EXPECT_LT(worst_grasp, 2e-4) << "rad past the share the twin loses";
}

TEST(ShippedCalibration, PutsThe2armReplaysWithinTheRobotsOwnSpread) {
  auto paper = paper2arm();
  if (!paper) GTEST_SKIP() << "../shared/data is absent: the paper's recordings are needed";
  const auto profile = twin::CalibrationProfile::shipped();
  paper->setup.controller.iteration_overhead = profile.iteration_overhead;
  profile.applyTo(paper->setup.twin);
  const auto score = calibration::scoreReplays(paper->setup, paper->physical);
  ASSERT_EQ(score.replays.size(), 3u);
  for (std::size_t k = 0; k < analysis::kActuatorSignals.size(); ++k) {
    const char* name = analysis::columnName(analysis::kActuatorSignals[k]);
    RecordProperty(name, std::to_string(score.actuators.median_ratio[k]));
    EXPECT_LE(score.actuators.median_ratio[k], 2.0)
        << name << ": the twin's difference from the robot over the robot's own spread";
  }
  for (std::size_t k = 0; k < 2; ++k) {
    const auto twin = score.twin[k].values();
    const auto robot = score.robot[k].values();
    for (std::size_t i = 0; i < 4; ++i) {
      const std::string name =
          calibration::Figures::names()[i] + (k ? ", first row removed" : ", as recorded");
      RecordProperty(name, std::to_string(twin[i]));
      EXPECT_LE(twin[i], robot[i])
          << name << ": twin " << twin[i] << ", the robot's own T_PP " << robot[i];
    }
  }
}

/// The starting values with each arm cable's friction on its motor (no cable stretch): what is
/// tested here is how motions are chosen, on a motor whose friction one value says.
twin::ArmsMechanics startingWithRigidCables() {
  auto m = calibration::startingMechanics();
  for (auto& arm : m) {
    arm.coulomb += arm.cable_friction;
    arm.cable_friction.setZero();
    arm.cable_travel.setZero();
  }
  return m;
}

/// A test robot whose friction the test knows and the fit does not: the starting values'
/// Coulomb friction, 40 % more on every motor.
twin::ArmsMechanics hiddenMechanics() {
  auto h = startingWithRigidCables();
  for (auto& m : h) m.coulomb *= 1.4;
  return h;
}

/// How many motors' Coulomb friction a fit found within 10 %.
int motorsIdentified(const twin::ArmsMechanics& fitted, const twin::ArmsMechanics& truth) {
  int n = 0;
  for (std::size_t a = 0; a < 2; ++a) {
    const raven::ArmJoints error =
        (fitted[a].coulomb - truth[a].coulomb).cwiseAbs().cwiseQuotient(truth[a].coulomb);
    n += static_cast<int>((error.array() <= 0.1).count());
  }
  return n;
}

/// Records on the test robot the motion each round's strategy picks among the same random
/// candidates, refits the friction, and returns how many motors are identified after each round.
std::vector<int> identify(bool proposed, int rounds) {
  const auto truth = hiddenMechanics();
  twin::CalibrationProfile profile;
  profile.mechanics = startingWithRigidCables();
  for (auto& u : profile.uncertainty) {
    for (std::size_t k = 0; k < twin::MotorMechanics::kNames.size(); ++k) u.field(k).setZero();
  }
  for (std::size_t a = 0; a < 2; ++a)
    profile.uncertainty[a].coulomb = 0.5 * profile.mechanics[a].coulomb;
  const auto prior = calibration::MechanicsInformation::fromUncertainty(profile.uncertainty);
  calibration::ReplaySetup setup;
  setup.controller.iteration_overhead = 0.001;
  std::vector<analysis::ActuatorTrace> recordings;
  std::vector<int> identified;
  for (int round = 0; round < rounds; ++round) {
    std::mt19937_64 random(100 + static_cast<unsigned>(round));
    calibration::MechanicsInformation known = prior;
    for (const auto& r : recordings) known += calibration::informationOf(profile.mechanics, r);
    std::vector<calibration::Candidate> candidates;
    for (int c = 0; c < 4; ++c) {
      candidates.push_back(calibration::scoreCandidate(
          setup, profile, known, calibration::randomExcitation(random, {6.0, 0.022})));
    }
    const calibration::Candidate* pick = &candidates[0];
    for (const auto& c : candidates) {
      if (proposed && c.within_limits && c.log_det > pick->log_det) pick = &c;
    }
    calibration::ReplaySetup on_robot = setup;
    on_robot.inputs = pick->inputs;
    on_robot.twin.motors = truth;
    recordings.push_back(analysis::actuatorTrace(calibration::recordReplay(on_robot)));
    calibration::ActuationFitOptions options;
    options.evaluations_per_joint = 15;
    options.sweeps = 1;
    options.same_motion = false;
    options.fields = {1};  // Coulomb friction
    profile.mechanics = calibration::fitActuation(recordings, profile.mechanics, options).mechanics;
    identified.push_back(motorsIdentified(profile.mechanics, truth));
  }
  return identified;
}

TEST(ActiveLearning, ProposedMotionsIdentifyAHiddenRobotInFewerRecordingsThanRandomOnes) {
  spdlog::set_level(spdlog::level::warn);
  // Each round draws the same four random 6 s candidates for both strategies: the proposal
  // takes the one with the most information, the random strategy the first.
  const auto proposed = identify(true, 2);
  const auto random = identify(false, 2);
  for (std::size_t k = 0; k < proposed.size(); ++k) {
    RecordProperty("identified_after_" + std::to_string(k + 1) + "_proposed", proposed[k]);
    RecordProperty("identified_after_" + std::to_string(k + 1) + "_random", random[k]);
  }
  EXPECT_EQ(proposed[0], 14) << "every motor's friction within 10 % after one proposed recording";
  EXPECT_LT(random[0], 14) << "one random recording leaves some motor unidentified";
  EXPECT_EQ(random[1], 14) << "two random recordings identify every motor";
}

}  // namespace
