#pragma once
// One arm's scripted peg transfers: for each peg, orient the grasper over it, descend, align the
// measured tool with the grasp, close, lift, carry, lower, open and retreat; a ring that does not
// follow the jaws or lands off its post is grasped again (at most twice), as an operator watching
// it would. Each call gives the next manual-loop target (at most a millimetre or 0.05 rad from the
// last), which the controller then reaches under its caps, exactly as it would a gamepad's.
// Positions move with the wrist-locked IK C_W. It sees the rings only as a ScenePerception reports
// them (poses), so it runs the same on the in-process twin, the twin over ROS and, with a tracker,
// the physical robot.

#include <optional>
#include <string_view>
#include <vector>

#include "bridge/scene_perception.hpp"
#include "raven/arm_kinematics.hpp"
#include "scenario/peg_layout.hpp"
#include "scenario/ring_view.hpp"

namespace scenario {

/// The steps of one transfer.
enum class Phase { Orient, Descend, Align, Close, Lift, Carry, Lower, Open, Settle, Retreat, Done };

std::string_view phaseName(Phase phase);

/// Scripted operator for one arm.
class ArmRoutine {
 public:
  /// `squeeze`: how far (m) the closed jaws reach into the ring's wall (grip_geometry.hpp).
  ArmRoutine(raven::Arm arm, const raven::PlatformProfile& profile, const PegLayout& layout,
             std::vector<RingJob> jobs, double squeeze = kDefaultSqueeze);

  /// 0.30 mm of the silicone ring's 4 mm wall: with the jaws kept at the grasp's opening
  /// (keepGrip) each jaw then presses on the nominal scene's rings with 1.6-2.8 N, within the few
  /// tenths to few newtons a grasper puts on a small silicone ring and harder than the 0.33-0.43 N
  /// measured in box-trainer peg transfers (../shared/reference/soft-materials.md); shallower
  /// grips slip more on the way (docs/main-job.md).
  static constexpr double kDefaultSqueeze = 0.00030;

  /// The arm's next target. `target` is its current one, `measured` where its encoders say it
  /// is, `scene` shows the rings. Where the arm stops short of its target (friction, a load),
  /// the operator watches the tool and makes the difference up before closing the jaws.
  raven::ArmJoints next(const raven::ArmJoints& target, const raven::ArmJoints& measured,
                        const bridge::ScenePerception& scene);
  /// Takes up the task from what `scene` shows and the arm's `target` (its current command), as
  /// an operator handed the pad mid-task would: the first ring not on its target post, and the
  /// step of its transfer the tool, the jaws and the ring show (getting to the grasp, gripping,
  /// carrying, letting go). While that is the step the routine is in, it goes on as it was (its
  /// waits keep counting); otherwise it starts that step afresh. So where someone else drove
  /// (a policy in DAgger), next() answers from the state reached, not from the routine's past.
  void resume(const raven::ArmJoints& target, const bridge::ScenePerception& scene);
  bool done() const { return phase_ == Phase::Done; }
  Phase phase() const { return phase_; }
  raven::Arm arm() const { return arm_; }
  /// True when the ring of the current job is off the board (the jaws have it).
  bool carrying(const bridge::ScenePerception& scene) const {
    return !done() && ringFollows(scene);
  }
  /// The outer jaw's angle that reaches `squeeze` (m) into a ring's wall, the grasper placed as
  /// the routine places it.
  double jawAngleFor(double squeeze) const;
  /// The jaws' commanded opening (jaw1 + jaw2) of the last target.
  double opening() const { return inner_ + outer_; }
  /// Jobs finished (whatever their outcome).
  std::size_t finished() const { return job_; }
  /// Per job, how often the operator opened and grasped its ring again: it did not come up with
  /// the jaws, slipped out on the way, or landed off its target post (at most twice a ring, with
  /// the same squeeze: within the 0.5-3 N a grasp may press with).
  const std::vector<int>& regrasps() const { return regrasps_; }
  const std::vector<RingJob>& jobs() const { return jobs_; }
  /// Where the tool point goes for the current job's grasp (planned when the job starts).
  const Eigen::Vector3d& graspPivot() const { return grasp_.pivot; }

 private:
  /// Where the grasp of the current job sits, measured from the ring when it starts.
  struct Grasp {
    Eigen::Matrix3d orientation;  ///< jaws down, turning about the ring's tangent
    Eigen::Vector3d pivot;        ///< the jaw axis at the grasp
    Eigen::Vector2d offset;       ///< the jaw axis from the ring's centre, horizontally
    /// The same when the ring came up with the jaws: a ring in the jaws stays near it.
    Eigen::Vector2d lifted_offset = Eigen::Vector2d::Zero();
  };
  /// The current job's ring as `scene` sees it.
  RingView ring(const bridge::ScenePerception& scene) const;
  /// The grasp of the current job on `seen`'s side `toward` (a horizontal direction).
  Grasp graspOn(const RingView& seen, const Eigen::Vector2d& toward) const;
  /// The horizontal direction from the ring's centre to the side its grasp takes: the one with
  /// the most room between the tube and the post the ring is on.
  Eigen::Vector2d graspSide(const RingView& seen) const;
  /// The joints (within the limits, nearest `target`) that hold the jaws open over the grasp.
  std::optional<raven::ArmJoints> overRing(const raven::ArmJoints& target) const;
  /// Moves the tool point towards `goal` by at most `step`, the wrist locked.
  raven::ArmJoints translate(const raven::ArmJoints& target, const Eigen::Vector3d& goal,
                             double step, bool& arrived) const;
  raven::ArmJoints withJaws(raven::ArmJoints q) const;
  void advance(Phase next);
  /// True when each measured jaw is within kJawReached of its command.
  bool jawsOnCommand(const raven::ArmJoints& measured) const;
  /// Holding a ring: trims the outer jaw's command so the measured opening comes to the grasp's.
  void keepGrip(const raven::ArmJoints& measured);
  /// True when the measured roll and wrist are within kJawReached of `target`'s, and the jaws on
  /// their command.
  bool toolOnCommand(const raven::ArmJoints& target, const raven::ArmJoints& measured) const;
  /// True when the measured tool lags a moving command by more than the motors' tracking does.
  bool blocked(const raven::ArmJoints& target, const raven::ArmJoints& measured) const;
  /// The command back to where the tool is, and what a person does next: a blocked descent is
  /// grasped again, a blocked alignment closes where it is, a blocked lowering lets the ring go;
  /// other moves go on from there.
  raven::ArmJoints easeOff(const raven::ArmJoints& measured);
  /// True when the ring of the current job left the board with the jaws.
  bool ringFollows(const bridge::ScenePerception& scene) const;
  /// Counts a re-grasp of the current job and marks it to be started again, unless it had its
  /// two; logs `why`.
  bool decideToRegrasp(const char* why);
  /// The current phase's command from `target` (the controller's current one), and whether it
  /// moves on; one step per phase below for the longer ones.
  raven::ArmJoints stepPhase(const raven::ArmJoints& target, const raven::ArmJoints& measured,
                             const bridge::ScenePerception& scene);
  raven::ArmJoints orient(const raven::ArmJoints& target, const bridge::ScenePerception& scene);
  raven::ArmJoints align(const raven::ArmJoints& target, const raven::ArmJoints& measured);
  raven::ArmJoints carry(const raven::ArmJoints& target, const bridge::ScenePerception& scene);
  raven::ArmJoints lower(const raven::ArmJoints& target, const bridge::ScenePerception& scene);
  raven::ArmJoints retreat(const raven::ArmJoints& target);
  /// What `resume` would take the current job up with: the phase the state shows, the grasp
  /// (planned anew unless `planned`) and whether the job starts again after it.
  struct TakenUp {
    Phase phase;
    Grasp grasp;
    bool retrying;
  };
  TakenUp shownStep(const raven::ArmJoints& target, const bridge::ScenePerception& scene,
                    bool planned) const;
  /// The debug line of a phase change of job `job`, the tool at `q`.
  void logTransition(Phase before, std::size_t job, const raven::ArmJoints& q,
                     const bridge::ScenePerception& scene) const;

  raven::Arm arm_;
  raven::PlatformProfile profile_;
  raven::ArmKinematics kinematics_;
  PegLayout layout_;
  std::vector<RingJob> jobs_;
  std::size_t job_ = 0;
  std::vector<int> regrasps_;  ///< per job
  bool retrying_ = false;      ///< the current job starts again after the retreat
  Phase phase_ = Phase::Orient;
  int waited_ = 0;
  Grasp grasp_;
  Eigen::Vector3d last_tool_ = Eigen::Vector3d::Zero();  ///< the measured tool, last iteration
  double closed_;                                        ///< the outer jaw's angle when closed
  double inner_ = 0.0, outer_ = 1.3;  ///< jaw angles: the inner one stays near vertical
};

}  // namespace scenario
