// One trial on the twin, driven by a virtual participant through SDL's virtual joystick (the
// path a person's pad takes): the recordings and events are written, and the metrics read back
// from them agree with what happened.

#include <gtest/gtest.h>

#include <fstream>

#include "harness/temp_dir.hpp"
#include "harness/virtual_gamepad.hpp"
#include "recording/recording_io.hpp"
#include "study/trial_metrics.hpp"
#include "study/trial_runner.hpp"
#include "study/virtual_participant.hpp"

namespace {

namespace fs = std::filesystem;

Sint16 raw(double v) {
  return static_cast<Sint16>(std::clamp(std::lround(v * 32768.0), -32768L, 32767L));
}

TEST(Trial, AVirtualParticipantReachesTargetsThroughTheVirtualPad) {
  controller::SdlGamepad pad(controller::TriggerScale::XboxOne, controller::Polling::Caller);
  harness::VirtualGamepad thumbs;
  ASSERT_TRUE(thumbs.ok()) << SDL_GetError();
  thumbs.axis(SDL_CONTROLLER_AXIS_TRIGGERLEFT, -32768);  // released triggers
  thumbs.axis(SDL_CONTROLLER_AXIS_TRIGGERRIGHT, -32768);
  pad.poll();
  harness::TempDir dir;
  study::TrialSettings s;
  s.task.count = 2;
  s.task.distance = 0.01;
  s.task.time_limit = 40.0;
  s.condition.scheme = "m2";
  s.task_seed = 5;
  s.dir = dir.path() / "trial";
  s.pad = &pad;
  study::VirtualParticipant vp(study::ParticipantTraits::draw(11),
                               study::ConditionFeel::of(s.condition, 0), 12);
  int iterations = 0;
  s.before_turn = [&](double t, const std::array<study::ArmGoal, 2>& goals,
                      const std::array<Eigen::Vector3d, 2>& tips) {
    const recording::GamepadState p = vp.act(t, goals, tips);
    thumbs.axis(SDL_CONTROLLER_AXIS_LEFTX, raw(p.left_x));
    thumbs.axis(SDL_CONTROLLER_AXIS_LEFTY, raw(p.left_y));
    thumbs.axis(SDL_CONTROLLER_AXIS_RIGHTX, raw(p.right_x));
    thumbs.axis(SDL_CONTROLLER_AXIS_RIGHTY, raw(p.right_y));
    thumbs.button(SDL_CONTROLLER_BUTTON_LEFTSHOULDER, p.left_bumper);
    thumbs.button(SDL_CONTROLLER_BUTTON_RIGHTSHOULDER, p.right_bumper);
    pad.poll();
    ++iterations;
  };
  const study::TrialRun run = study::runTrial(s);
  ASSERT_TRUE(run.finished);
  EXPECT_TRUE(run.completed);
  EXPECT_LT(run.duration, 40.0);

  // Everything the controller records, one row per manual iteration, and the events.
  fs::path rs, ci, cf;
  for (const auto& e : fs::directory_iterator(s.dir)) {
    const std::string name = e.path().filename().string();
    if (name.ends_with("_rs.csv")) rs = e.path();
    if (name.ends_with("_ci.csv")) ci = e.path();
    if (name.ends_with("_cf.csv")) cf = e.path();
  }
  ASSERT_FALSE(rs.empty());
  ASSERT_FALSE(cf.empty());
  const auto inputs = recording::readCi(ci);
  EXPECT_EQ(inputs.size(), static_cast<std::size_t>(iterations));
  EXPECT_EQ(recording::readRs(rs).rows.size(), inputs.size());
  EXPECT_TRUE(inputs.front().a);  // the wrist-locked IK asked for on the first iteration
  EXPECT_FALSE(inputs.front().b);
  for (const auto& p : inputs) {
    EXPECT_DOUBLE_EQ(p.left_trigger, 0.0);
    EXPECT_FALSE(p.back || p.start);  // M2's scheme cannot be switched
  }

  const study::TrialMetrics m = study::measureTrial(s.dir);
  EXPECT_EQ(m.at("completed"), 1.0);
  EXPECT_EQ(m.at("targets_reached"), 4.0);  // two per arm
  EXPECT_NEAR(m.at("completion_time_s"), run.duration, 1e-3);
  // Both tips went at least to their targets and back towards the next.
  EXPECT_GT(m.at("path_length_m"), 2 * 0.01 - 2 * 0.003);
  EXPECT_LT(m.at("sparc"), 0.0);
  EXPECT_TRUE(std::isnan(m.at("rings_placed")));        // not a peg task
  EXPECT_TRUE(std::isnan(m.at("peak_grasp_force_n")));  // nothing was grasped
  EXPECT_TRUE(std::isnan(m.at("board_collisions")));    // no board
  EXPECT_EQ(m.at("instrument_collisions"), 0.0);
  EXPECT_EQ(m.at("excessive_force_time_s"), 0.0);
  EXPECT_EQ(m.at("out_of_view_time_s"), 0.0);  // the task camera holds every target
  // Each tip went to targets 10 mm out and up to 5 mm up from its start (within 3 mm): a
  // workspace radius of at least half of 10 - 3 mm, at most twice the 14.2 mm it can reach.
  for (const char* range : {"tip_range_left_m", "tip_range_right_m"}) {
    EXPECT_GT(m.at(range), 0.003) << range;
    EXPECT_LT(m.at(range), 0.03) << range;
  }
  EXPECT_GT(m.at("stick_range_left"), 0.1);
}

TEST(Trial, TheGateKeepsTheConditionsSchemeAndIk) {
  study::Condition m1;
  m1.scheme = "m1";
  m1.full_ik = true;
  recording::GamepadState p;
  p.back = p.start = p.a = true;
  auto gated = study::gatePad(m1, p, true);
  EXPECT_FALSE(gated.back || gated.start);  // both together would select M2
  EXPECT_TRUE(gated.b);
  EXPECT_FALSE(gated.a);
  p.start = false;
  gated = study::gatePad(m1, p, false);
  EXPECT_TRUE(gated.back);  // M1 chooses its arm
  EXPECT_FALSE(gated.a || gated.b);
  study::Condition m2;
  EXPECT_FALSE(study::gatePad(m2, p, false).back);
  EXPECT_EQ(study::armsMoved(study::Condition{.name = "", .scheme = "m1-left"}),
            (std::array<bool, 2>{true, false}));
}

// -1.4058 is the published algorithm computed with NumPy's FFT on the same profile.
TEST(Trial, SparcOfOneMinimumJerkReachIsMinusOnePointFourAndLowerWithCorrections) {
  std::vector<double> smooth, corrected;
  for (double t = 0.0; t <= 1.0; t += 0.01) {  // a minimum-jerk speed profile over 1 s
    smooth.push_back(30.0 * t * t * (1 - t) * (1 - t));
  }
  corrected = smooth;
  for (double t = 0.0; t <= 0.6; t += 0.01) {  // then two corrections
    corrected.push_back(8.0 * std::pow(std::sin(M_PI * t / 0.3), 2));
  }
  const double s = study::sparc(smooth, 100.0);
  EXPECT_NEAR(s, -1.4058, 0.001);
  EXPECT_LT(study::sparc(corrected, 100.0), s - 0.3);
  EXPECT_TRUE(std::isnan(study::sparc(std::vector<double>(50, 0.0), 100.0)));
}

TEST(Trial, ABrokenEventsFileIsRefusedNamingTheRow) {
  harness::TempDir dir;
  dir.write("events.csv", "time,event,arm,value\n0.0,trial_start,-1,0\nx,trial_end,-1,1\n");
  try {
    study::measureTrial(dir.path());
    FAIL() << "a bad row was accepted";
  } catch (const recording::RecordingError& e) {
    EXPECT_NE(std::string(e.what()).find("events.csv: row 3"), std::string::npos) << e.what();
  }
}

}  // namespace

namespace {

TEST(Trial, ThePegTransferTaskWatchesTheRingsAndTheBoard) {
  // No person and no virtual participant here: the trial starts the left grasper 45 mm over the
  // board, and the left stick held down (bumper: along z) by a scripted reading takes it into
  // the board and its command on below it.
  controller::SdlGamepad pad(controller::TriggerScale::XboxOne, controller::Polling::Caller);
  harness::VirtualGamepad thumbs;
  ASSERT_TRUE(thumbs.ok()) << SDL_GetError();
  thumbs.axis(SDL_CONTROLLER_AXIS_TRIGGERLEFT, -32768);
  thumbs.axis(SDL_CONTROLLER_AXIS_TRIGGERRIGHT, -32768);
  thumbs.axis(SDL_CONTROLLER_AXIS_LEFTY, 32767);  // with the bumper: -z
  thumbs.button(SDL_CONTROLLER_BUTTON_LEFTSHOULDER, true);
  pad.poll();
  harness::TempDir dir;
  study::TrialSettings s;
  s.task.kind = study::TaskKind::PegTransfer;
  s.task.time_limit = 15.0;
  s.dir = dir.path() / "rings";
  s.pad = &pad;
  s.before_turn = [&](double t, const auto&, const auto&) {
    if (t >= 10.0) thumbs.axis(SDL_CONTROLLER_AXIS_LEFTY, 0);
    pad.poll();
  };
  const study::TrialRun run = study::runTrial(s);
  ASSERT_TRUE(run.finished);
  EXPECT_FALSE(run.completed);
  // Held down on the board, the left arm's motors wind up against it until an amplifier passes
  // its overdrive threshold and the robot e-stops, as the physical robot does; the e-stop ends
  // the trial. On the way its jaw pressed on the board harder than the 3 N a grasp of tissue
  // takes.
  EXPECT_TRUE(run.e_stopped);
  const study::TrialMetrics m = study::measureTrial(s.dir);
  EXPECT_EQ(m.at("e_stops"), 1.0);
  EXPECT_EQ(m.at("completed"), 0.0);
  EXPECT_GT(run.duration, 1.0);
  EXPECT_LT(run.duration, 10.0);  // before the stick was let go
  // Not finished: it counts at the time limit, not at the few seconds the e-stop left it.
  EXPECT_EQ(m.at("completion_time_s"), 15.0);
  EXPECT_GT(m.at("excessive_force_time_s"), 0.0);
  EXPECT_GT(m.at("excessive_force_peak_n"), 3.0);
  EXPECT_EQ(m.at("rings_placed"), 0.0);
  EXPECT_EQ(m.at("rings_dropped"), 0.0);
  // One touch of the board, held: one collision; no post, the other arm untouched.
  EXPECT_EQ(m.at("board_collisions"), 1.0);
  EXPECT_EQ(m.at("post_collisions"), 0.0);
  EXPECT_EQ(m.at("tool_collisions"), 0.0);
  EXPECT_EQ(m.at("instrument_collisions"), 1.0);
  EXPECT_EQ(m.at("out_of_view_time_s"), 0.0);  // the overview shows both work areas
  // The stick at full tilt from the first reading to the end: no range; nor the right one.
  EXPECT_EQ(m.at("stick_range_left"), 0.0);
  EXPECT_EQ(m.at("stick_range_right"), 0.0);
  EXPECT_GT(m.at("tip_range_left_m"), 0.005);
  EXPECT_TRUE(std::isnan(m.at("targets_reached")));
}

}  // namespace

namespace {

TEST(Trial, AVideoOfTheTrialIsWrittenBesideItsRecordings) {
  controller::SdlGamepad pad(controller::TriggerScale::XboxOne, controller::Polling::Caller);
  harness::VirtualGamepad thumbs;  // left alone: the arms stay where they are
  ASSERT_TRUE(thumbs.ok()) << SDL_GetError();
  thumbs.axis(SDL_CONTROLLER_AXIS_TRIGGERLEFT, -32768);
  thumbs.axis(SDL_CONTROLLER_AXIS_TRIGGERRIGHT, -32768);
  pad.poll();
  harness::TempDir dir;
  study::TrialSettings s;
  s.task.count = 1;
  s.task.time_limit = 1.0;  // the pad left alone: the trial runs to its limit
  s.dir = dir.path() / "trial";
  s.pad = &pad;
  viewer::VideoOptions video;
  video.fps = 10;
  video.width = 320;
  video.height = 180;
  s.video = video;
  try {
    study::runTrial(s);
  } catch (const std::runtime_error& e) {
    GTEST_SKIP() << "no headless OpenGL: " << e.what();
  }
  ASSERT_TRUE(fs::exists(s.dir / "trial.mp4"));
  EXPECT_GT(fs::file_size(s.dir / "trial.mp4"), 1000u);
  EXPECT_EQ(study::measureTrial(s.dir).at("completed"), 0.0);
}

}  // namespace
