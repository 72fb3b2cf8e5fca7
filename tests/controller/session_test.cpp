// The controller end to end: an SDL virtual gamepad drives the twin as the mapping says (and
// rumbles at a limit, and an unplug stops motion); replays on the simulated clock equal replays
// in real time; the paper's inputs replayed on the twin land within the physical robot's own
// repeatability.

#include "controller/session.hpp"

#include <SDL2/SDL.h>
#include <gtest/gtest.h>

#include "analysis/metrics.hpp"
#include "harness/virtual_gamepad.hpp"
#include "test_files.hpp"
#include "twin/twin_platform.hpp"
#include "twin_fixtures.hpp"

namespace {

using controller::Mode;
using raven::Arm;
using recording::GamepadState;

/// A homed in-process twin on `clock`.
std::unique_ptr<twin::TwinPlatform> readyTwin(
    bridge::ClockKind clock = bridge::ClockKind::Simulated) {
  twin::TwinOptions options;
  options.clock = clock;
  return test_support::readyTwin(options);
}

Eigen::Vector3d leftWrist(const bridge::RavenPlatform& robot) {
  static const auto kin = raven::ArmKinematics::of(raven::builtinProfile("physical"), Arm::Left);
  return kin.wristPoint(robot.measuredJs(Arm::Left).position);
}

using VirtualPad = harness::VirtualGamepad;

TEST(Gamepad, AVirtualPadDrivesTheTwinAsTheMappingSays) {
  auto twin = readyTwin();
  controller::SdlGamepad pad(controller::TriggerScale::XboxOne, controller::Polling::Caller);
  VirtualPad device;
  ASSERT_TRUE(device.ok()) << SDL_GetError();
  device.axis(SDL_CONTROLLER_AXIS_LEFTX, 16384);  // 0.5: +0.25 mm per iteration
  pad.poll();
  ASSERT_TRUE(pad.read()) << "SDL did not see the virtual pad as a game controller";
  EXPECT_EQ(pad.read()->left_x, 0.5);
  EXPECT_EQ(pad.name(), "virtual gamepad");

  controller::DualPlatformController control(
      {{"twin", twin.get(), controller::CommandStyle::ServoJr}}, {});
  controller::ControllerSession session(control, {&pad, {}, std::nullopt}, {});
  ASSERT_TRUE(session.select(Mode::Manual));
  const Eigen::Vector3d start = leftWrist(*twin);
  for (int i = 0; i < 40; ++i) {
    pad.poll();
    session.turn();
  }
  twin->advance(0.05);
  const Eigen::Vector3d moved = leftWrist(*twin) - start;
  EXPECT_NEAR(moved.x(), 40 * 0.00025, 2e-6);
  EXPECT_NEAR(moved.y(), 0.0, 2e-6);
  EXPECT_NEAR(moved.z(), 0.0, 2e-6);

  // Down into the insertion's limit: the IK clamps and the pad rumbles.
  device.axis(SDL_CONTROLLER_AXIS_LEFTX, 0);
  device.axis(SDL_CONTROLLER_AXIS_LEFTY, 32767);
  device.button(SDL_CONTROLLER_BUTTON_LEFTSHOULDER, true);
  for (int i = 0; i < 400 && device.rumbles == 0; ++i) {
    pad.poll();
    session.turn();
    pad.poll();  // delivers the rumble the turn asked for
  }
  EXPECT_GT(device.rumbles, 0);

  // Unplugged mid-run: no more motion, and the session says so.
  device.unplug();
  pad.poll();
  EXPECT_FALSE(pad.read());
  EXPECT_EQ(pad.unplugs(), 1u);
  const auto held = twin->setpointJs(Arm::Left).position;
  for (int i = 0; i < 20; ++i) session.turn();
  EXPECT_EQ(session.padlessTurns(), 20u);
  EXPECT_EQ(twin->setpointJs(Arm::Left).position, held);
}

TEST(Gamepad, TriggersAreScaledOntoThePapersRange) {
  EXPECT_DOUBLE_EQ(controller::SdlGamepad::trigger(32767, controller::TriggerScale::XboxOne),
                   1023.0 / 256.0);
  EXPECT_DOUBLE_EQ(controller::SdlGamepad::trigger(32767, controller::TriggerScale::EightBit),
                   255.0 / 256.0);
  EXPECT_DOUBLE_EQ(controller::SdlGamepad::stick(-32768), -1.0);
  EXPECT_DOUBLE_EQ(controller::SdlGamepad::stick(16384), 0.5);
}

/// Replays `inputs` with O3 on a fresh twin on `clock`, recording; returns the rs file.
recording::RsRecording replay(const std::vector<GamepadState>& inputs, bridge::ClockKind clock,
                              const std::filesystem::path& out) {
  auto twin = readyTwin(clock);
  controller::DualPlatformController control(
      {{"twin", twin.get(), controller::CommandStyle::ServoJr}}, {});
  controller::SessionOptions options;
  options.out_dir = out;
  options.replay_delay = 0.1;
  options.end_after_replay = true;
  controller::ControllerSession session(control, {nullptr, inputs, std::nullopt}, options);
  session.select(Mode::ReplayInputs);
  session.startRecording();
  while (session.turn()) {
  }
  session.stopRecording();
  return recording::readRs(session.recordings().front());
}

TEST(Replay, AJointReplayPastTheLimitsIsClampedAndSaysSo) {
  test_support::TempDir dir;
  const auto path = dir.path() / "far_rs.csv";
  {
    recording::RsWriter writer(path);
    const auto home = raven::builtinProfile("physical").home;
    for (int r = 0; r < 5; ++r) {
      bridge::RavenStateSnapshot s;
      s.time = 0.001 * r;
      for (int j = 0; j < raven::kJointCount; ++j) {
        s.jpos[static_cast<std::size_t>(j)] = static_cast<float>(home(j) * 180.0 / M_PI);
        s.jpos[static_cast<std::size_t>(8 + j)] = static_cast<float>(home(j) * 180.0 / M_PI);
      }
      if (r >= 2) s.jpos[0] = static_cast<float>(10.0 * 180.0 / M_PI);  // 10 rad on a shoulder
      writer.write(s);
    }
  }
  auto twin = readyTwin();
  controller::DualPlatformController control(
      {{"twin", twin.get(), controller::CommandStyle::ServoJr}}, {});
  controller::SessionOptions options;
  options.out_dir = dir.path();
  options.end_after_replay = true;
  controller::ControllerSession session(control, {nullptr, {}, recording::readRs(path)}, options);
  session.select(Mode::ReplayJoints);
  while (session.turn()) {
  }
  EXPECT_EQ(session.clampedRows(), 3u);
}

TEST(Replay, TheSimulatedClockGivesTheSameRowsAsRealTime) {
  std::vector<GamepadState> inputs(60);
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    inputs[i].left_x = std::sin(0.1 * static_cast<double>(i));
    inputs[i].right_y = -0.8;
    inputs[i].left_trigger = i > 30 ? 2.0 : 0.0;
  }
  test_support::TempDir dir;
  const auto fast = replay(inputs, bridge::ClockKind::Simulated, dir.path() / "fast");
  const auto paced = replay(inputs, bridge::ClockKind::Wall, dir.path() / "paced");
  ASSERT_EQ(fast.rows.size(), 60u);
  ASSERT_EQ(paced.rows.size(), 60u);
  for (std::size_t r = 0; r < fast.rows.size(); ++r) {
    for (int j = 0; j < 16; ++j) {
      const auto c = fast.column("jpos" + std::to_string(j));
      ASSERT_EQ(fast.rows[r][c], paced.rows[r][c]) << "row " << r << " jpos" << j;
    }
    ASSERT_EQ(fast.time(r), paced.time(r));
  }
}

TEST(Replay, ThePapersInputsOnTheTwinLandWithinThePhysicalRobotsRepeatability) {
  const auto shared = test_support::sharedDataDir();
  if (shared.empty()) GTEST_SKIP() << "../shared/data is absent: the paper's recordings are needed";
  const auto dir = shared / "recordings/paper_2arm";
  auto twin = readyTwin();
  controller::ControllerOptions options;
  options.mapping.deadzone_reads_y_twice = true;  // as the released controller recorded them
  controller::DualPlatformController control(
      {{"twin", twin.get(), controller::CommandStyle::ServoJr}}, options);
  test_support::TempDir out;
  controller::SessionOptions session_options;
  session_options.out_dir = out.path();
  session_options.end_after_replay = true;
  controller::ControllerSession session(
      control, {nullptr, recording::readCi(dir / "2arm_ci.csv"), std::nullopt}, session_options);
  session.select(Mode::ReplayInputs);
  session.startRecording();
  while (session.turn()) {
  }
  session.stopRecording();
  ASSERT_EQ(recording::readRs(session.recordings().front()).rows.size(), 1351u);
  // Named as the twin's, beside the three physical replays of the same inputs.
  const auto twin_file = out.path() / "twin_paper_2arm_rs.csv";
  std::filesystem::rename(session.recordings().front(), twin_file);
  std::vector<std::filesystem::path> files{twin_file};
  for (int k = 1; k <= 3; ++k)
    files.push_back(dir / ("2arm_physical_" + std::to_string(k) + ".csv"));
  const auto set = analysis::loadTrials(
      files, analysis::readRecordingSources(analysis::defaultRecordingSourcesFile()));
  ASSERT_NE(set.find("twin"), nullptr);
  ASSERT_NE(set.find("physical"), nullptr);
  const analysis::Comparison twin_vs_physical{set.find("twin"), set.find("physical")};
  const auto position = analysis::Quantity::Position;
  const double revolute =
      analysis::groupFigure(twin_vs_physical, analysis::revoluteJoints(), position, false);
  const double insertion =
      analysis::groupFigure(twin_vs_physical, analysis::prismaticJoints(), position, false);
  RecordProperty("revolute_rad", std::to_string(revolute));
  RecordProperty("insertion_mm", std::to_string(insertion));
  EXPECT_LE(revolute, 0.0135);
  EXPECT_LE(insertion, 1.4);
}

}  // namespace
