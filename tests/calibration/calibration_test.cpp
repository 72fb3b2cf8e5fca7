// raven_calibrate's parts: the recording controller's measured timing, the fit's objective and
// parameters, the profile it writes, and the shipped calibration of the paper's 2arm set, which
// must put the twin within the robot's own repeatability in positions and velocities.

#include <gtest/gtest.h>

#include <cmath>

#include "calibration/calibration_file.hpp"
#include "calibration/replay_timing.hpp"
#include "calibration/tracking_fit.hpp"
#include "test_files.hpp"

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

TEST(TrackingFit, ParametersMapOntoTheDriveGroups) {
  const auto& parameters = calibration::trackingParameters();
  ASSERT_EQ(parameters.size(), 13u);  // latency + 4 drives x (bandwidth, damping, friction)
  std::vector<double> values;
  for (const auto& p : parameters) values.push_back(p.initial);
  values[0] = 3.5;    // latency
  values[7] = 4.0;    // insertion bandwidth
  values[9] = 0.001;  // insertion friction deadband
  values[10] = 40.0;  // instrument bandwidth
  const auto t = calibration::toTracking(values);
  EXPECT_EQ(t.latency_cycles, 3.5);
  EXPECT_EQ(t.bandwidth_hz(raven::kInsertion), 4.0);
  EXPECT_EQ(t.friction_deadband(raven::kInsertion), 0.001);
  for (int j : {raven::kRoll, raven::kWrist, raven::kJaw1, raven::kJaw2}) {
    EXPECT_EQ(t.bandwidth_hz(j), 40.0) << "the instrument's joints share their drive's values";
  }
  EXPECT_TRUE(t.invalidReason().empty()) << t.invalidReason();
  EXPECT_THROW(calibration::toTracking({1.0}), std::invalid_argument);
  for (const auto& p : parameters) {
    EXPECT_LE(p.lower, p.initial);
    EXPECT_LE(p.initial, p.upper);
  }
}

TEST(TrackingFit, TheScoreIsTheMeanOfTheFiguresOverTheRobotsOwn) {
  const calibration::Figures robot{0.01, 1.0, 0.1, 0.2};
  EXPECT_DOUBLE_EQ(calibration::fidelityScore(robot, robot), 1.0);
  EXPECT_DOUBLE_EQ(calibration::fidelityScore({0.02, 1.0, 0.1, 0.1}, robot), (2 + 1 + 1 + 0.5) / 4);
}

TEST(CalibrationFile, WhatIsWrittenIsReadBack) {
  test_support::TempDir dir;
  twin::CalibrationProfile profile;
  profile.tracking = calibration::toTracking(
      {8.25, 19.5, 1.0, 0.001, 21.0, 0.9, 0.0, 4.5, 1.05, 0.0002, 20.0, 1.0, 0.003});
  profile.iteration_overhead = 0.001;
  calibration::writeCalibration(dir.path() / "c.yaml", profile,
                                {"inputs_ci.csv", {"a_physical_1.csv"}, {"a note"}});
  const auto read = twin::CalibrationProfile::load(dir.path() / "c.yaml");
  EXPECT_NEAR(read.tracking.latency_cycles, 8.25, 1e-9);
  EXPECT_TRUE(read.tracking.bandwidth_hz.isApprox(profile.tracking.bandwidth_hz, 1e-6));
  EXPECT_TRUE(read.tracking.damping_ratio.isApprox(profile.tracking.damping_ratio, 1e-6));
  EXPECT_TRUE(read.tracking.friction_deadband.isApprox(profile.tracking.friction_deadband, 1e-6));
  EXPECT_EQ(read.iteration_overhead, 0.001);
}

/// The paper's 2arm set: its inputs, the released controller's deadzone, the physical trials.
struct Paper2arm {
  calibration::ReplaySetup setup;
  analysis::PlatformTrials physical;
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
  const auto set =
      analysis::loadTrials(files, analysis::readProfiles(analysis::defaultProfilesFile()));
  p.physical = *set.find("physical");
  return p;
}

TEST(ShippedCalibration, PutsThe2armReplayWithinTheRobotsRepeatabilityInPositionsAndVelocities) {
  auto paper = paper2arm();
  if (!paper) GTEST_SKIP() << "../shared/data is absent: the paper's recordings are needed";
  const auto profile = twin::CalibrationProfile::load(RAVEN_SHIPPED_CALIBRATION);
  paper->setup.controller.iteration_overhead = profile.iteration_overhead;
  const auto twin = calibration::replayOnTwin(paper->setup, profile.tracking);
  ASSERT_EQ(twin.rows(), 1351u);
  const auto after = calibration::twinVsPhysical(twin, paper->physical).values();
  const auto robot = calibration::robotRepeatability(paper->physical).values();
  for (std::size_t i = 0; i < 4; ++i) {
    RecordProperty(calibration::Figures::names()[i], std::to_string(after[i]));
    EXPECT_LE(after[i], robot[i]) << calibration::Figures::names()[i] << ": twin " << after[i]
                                  << ", the robot's own T_PP " << robot[i];
  }
}

TEST(TrackingFit, AShortFitImprovesOnItsStartingPoint) {
  auto paper = paper2arm();
  if (!paper) GTEST_SKIP() << "../shared/data is absent: the paper's recordings are needed";
  paper->setup.controller.iteration_overhead = 0.001;
  const auto scale = calibration::robotRepeatability(paper->physical);
  std::vector<double> initial;
  for (const auto& p : calibration::trackingParameters()) initial.push_back(p.initial);
  const double start = calibration::fidelityScore(
      calibration::twinVsPhysical(
          calibration::replayOnTwin(paper->setup, calibration::toTracking(initial)),
          paper->physical),
      scale);
  calibration::FitOptions options;
  options.max_evaluations = 12;
  const auto fit = calibration::fitTracking(paper->setup, paper->physical, scale, options);
  EXPECT_EQ(fit.evaluations, 12);
  EXPECT_LE(fit.score, start);
  EXPECT_TRUE(fit.tracking.invalidReason().empty());
}

}  // namespace
