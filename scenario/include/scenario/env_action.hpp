#pragma once
// The peg-transfer environment's actions: both arms' joint targets, joint deltas from the
// current targets, or per arm a tool-tip displacement with the wrist locked (C_W) plus the jaws'
// opening. Each becomes joint targets, which the controller then clamps to the limits and
// reaches under the velocity caps.

#include <Eigen/Core>
#include <array>
#include <string_view>

#include "controller/arrival.hpp"
#include "controller/following_limit.hpp"
#include "controller/velocity_cap.hpp"
#include "raven/arm_kinematics.hpp"

namespace scenario {

/// What an action is.
enum class EnvAction {
  Joints,       ///< 14: both arms' joint targets, left first, ArmJoints order
  JointDeltas,  ///< 14: added to the current targets (at most a joint's range)
  /// 8: per arm dx, dy, dz of the tool tip (m, at most kMaxToolDelta each) in the controller's
  /// frame {B} (the frame a gamepad's sticks move the tool in), then the jaws' opening (rad)
  ToolDeltas
};

/// "joints", "joint_deltas", "tool_deltas"; throws std::invalid_argument naming the others.
EnvAction envActionNamed(std::string_view name);
int actionSize(EnvAction kind);

/// How far a step lets the robot's setpoint lead its measured joints where contact holds an arm
/// back (controller::ControllerOptions::following_limit), from the robot's control law and its
/// e-stop (../shared/reference/raven2-actuation.md §2.1, §3-4: |dac| 20000 counts; 3695.8 counts
/// per N m on the RE40 axes, 27328 on the RE30 tool axes; KP 0.30, 0.30, 0.15, 0.09, 0.05, 0.05,
/// 0.05 N m per motor rad): the positioning joints' lead at half the error at which their
/// proportional loop alone reaches the threshold (0.066 rad, 0.074 rad, 8.4 mm); the roll's,
/// wrist's and jaw 1's torque itself at half the threshold (0.366 N m), since their integrators
/// wind up under any lasting lead (GRASP2's command is never checked: none); `give` is
/// 1 / (KP x TR).
controller::FollowingLimit followingLimit();

/// When a step has arrived (controller::ControllerOptions::arrival), at the scripted operator's
/// own tolerances (ArmRoutine): the wrist's axis within 0.1 mm of its targets' (kAligned) or
/// stopped (under 20 um in a 20 ms iteration, kStill), the tool's joints within 0.01 rad
/// (kJawReached) or stopped (under 2 mrad in the same 20 ms); a stopped arm's shortfall made up
/// within 2 mm at the wrist (kAlignReach); at most half a second.
controller::Arrival arrival();

/// Largest tool displacement per step (m).
inline constexpr double kMaxToolDelta = 0.005;

/// An action's bounds (an action is clipped to them).
struct ActionBounds {
  Eigen::VectorXd low, high;
};
ActionBounds actionBounds(EnvAction kind, const raven::JointLimits& limits);

/// The joint targets `action` asks for from the current targets `current`, after clipping it to
/// its bounds. Throws std::invalid_argument for a wrong size or a value that is not finite,
/// naming its index. A tool displacement out of reach leaves that arm's position where it is.
controller::ArmPair targetsOf(EnvAction kind, const Eigen::VectorXd& action,
                              const controller::ArmPair& current,
                              const raven::PerArm<raven::ArmKinematics>& kinematics,
                              const raven::ArmJoints& home);

/// The action of `kind` that asks for `targets` from `current` (tool deltas: the tool tips'
/// displacement and the jaws' opening; a change of the wrist's joints is not expressible).
Eigen::VectorXd actionFor(EnvAction kind, const controller::ArmPair& targets,
                          const controller::ArmPair& current,
                          const raven::PerArm<raven::ArmKinematics>& kinematics);

}  // namespace scenario
