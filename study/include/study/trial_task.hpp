#pragma once
// The tasks a trial can run on the twin: reaching targets with the tool tips (random points,
// the paper's rectangle D_II, or listed points) and the peg transfer. A task watches the twin
// after every manual-loop iteration, logs its events, says when it is done, and tells what the
// participant aims for now (the goals a virtual participant steers to, the terminal's line).

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "scenario/ring_view.hpp"
#include "study/protocol.hpp"
#include "study/trial_events.hpp"
#include "twin/twin_platform.hpp"
#include "viewer/view.hpp"

namespace study {

/// What the task sees after an iteration.
struct TaskView {
  double time = 0.0;                    ///< s since the trial began
  raven::PerArm<Eigen::Vector3d> tips;  ///< tool tips, controller frame (m), left first
  raven::PerArm<Eigen::Vector3d> jaws;  ///< the jaws' axes, world frame (m), left first
  /// The tools' axes, controller frame, left first: x along the closed jaws, y the way jaw 1
  /// opens.
  raven::PerArm<Eigen::Matrix3d> tool_axes;
  const ambf_like::World* world = nullptr;
};

/// Where one arm should go now.
struct ArmGoal {
  bool active = false;  ///< false: this arm has nothing (more) to do
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  double tolerance = 0.0;
  double grasp = 1.0;  ///< the jaw opening wanted (jaw 1 + jaw 2, rad): 1 with the trigger let go
};

/// One task's progress through one trial.
class TrialTask {
 public:
  virtual ~TrialTask() = default;
  /// The scene: empty for our Raven-II alone.
  virtual std::filesystem::path launchFile() const = 0;
  /// Called once, with the homed twin, before the first iteration.
  virtual void begin(const TaskView& view, EventLog& events) = 0;
  /// Called after every iteration.
  virtual void observe(const TaskView& view, EventLog& events) = 0;
  virtual bool done() const = 0;
  virtual raven::PerArm<ArmGoal> goals() const = 0;
  /// One line for the terminal: what is left, how far.
  virtual std::string status(const TaskView& view) const = 0;
  /// The task camera, fixed in the world: what the trial's video shows, and what the jaws are
  /// out of view of.
  virtual viewer::View camera(const TaskView& start) const = 0;
  /// The board the tools may collide with, if the scene has one.
  virtual std::optional<scenario::BoardGeometry> board() const = 0;
  /// Where the trial starts each tool (controller frame, its jaws opened by the trigger let go),
  /// if the task sets it up: the lab places the instrument before the participant starts.
  virtual std::optional<raven::PerArm<Eigen::Isometry3d>> startTools() const = 0;
};

/// The task `spec` asks for; `seed` draws random targets; an arm `arms` leaves out gets none.
std::unique_ptr<TrialTask> makeTask(const TaskSpec& spec, std::uint64_t seed,
                                    raven::PerArm<bool> arms = {true, true});

/// The targets (offsets from each arm's start tip, m) a targets task shows, left arm first.
raven::PerArm<std::vector<Eigen::Vector3d>> targetOffsets(const TaskSpec& spec, std::uint64_t seed);

}  // namespace study
