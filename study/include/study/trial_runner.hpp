#pragma once
// One trial on the twin: the task's scene built and homed, the condition's controller, the
// participant's pad (a person's, or a virtual participant's through SDL's virtual joystick)
// read each manual-loop iteration through the condition's gate, everything the controller
// records (rs, ci, cf) plus the trial's events written to the trial's folder as it goes, and a
// video if asked for.

#include <atomic>
#include <filesystem>
#include <functional>
#include <string>

#include "controller/sdl_gamepad.hpp"
#include "study/protocol.hpp"
#include "study/trial_task.hpp"
#include "viewer/video_recorder.hpp"

namespace study {

/// Called before every iteration with the time (s since the trial began), the task's goals and
/// the tool tips: a virtual participant sets its pad here.
using BeforeTurn = std::function<void(double, const raven::PerArm<ArmGoal>&,
                                      const raven::PerArm<Eigen::Vector3d>&)>;

/// What a trial runs with.
struct TrialSettings {
  TaskSpec task;
  Condition condition;
  std::uint64_t task_seed = 0;
  std::filesystem::path dir;  ///< created; the recordings and events.csv go here
  bool wall_clock = false;    ///< a person: the twin in real time; else the simulated clock
  controller::SdlGamepad* pad = nullptr;
  BeforeTurn before_turn;
  /// Shown about ten times a second of trial time (a person's terminal); may be empty.
  std::function<void(const std::string&)> status;
  /// Called once the twin is homed, before the first iteration (a person's countdown); false
  /// stops the trial before it begins.
  std::function<bool()> ready;
  const std::atomic<bool>* stop = nullptr;  ///< set: the trial ends now, unfinished
  /// Set: a video of the trial (headless) to `dir`/trial.mp4 at this rate and size.
  std::optional<viewer::VideoOptions> video;
};

/// How a trial ended.
struct TrialRun {
  bool finished = false;   ///< ran to its end (done, the time limit, an e-stop), not stopped
  bool completed = false;  ///< the task was done within the time limit
  bool e_stopped = false;  ///< the robot went to FAULT, which ends a trial
  bool diverged = false;   ///< the simulation's guard stopped the world (a ring fell off it)
  double duration = 0.0;   ///< s of trial time
};

/// The pad reading the condition lets through: its scheme cannot be switched (M2 ignores Back
/// and Start, M1 lets one of them choose the arm, a one-arm M1 neither), its IK is set on the
/// first iteration (B for the full IK) and A / B are ignored after.
recording::GamepadState gatePad(const Condition& condition, recording::GamepadState pad,
                                bool first);

/// The arms a condition's scheme can move (left, right).
raven::PerArm<bool> armsMoved(const Condition& condition);

TrialRun runTrial(const TrialSettings& settings);

}  // namespace study
