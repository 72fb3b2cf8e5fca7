#pragma once
// The peg-transfer environment's actions: both arms' joint targets, joint deltas from the
// current targets, or per arm a tool-tip displacement with the wrist locked (C_W) plus the jaws'
// opening. Each becomes joint targets, which the controller then clamps to the limits and
// reaches under the velocity caps.

#include <Eigen/Core>
#include <array>
#include <string_view>

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
/// back (controller::ControllerOptions::following_limit): per positioning joint half the following
/// error at which the robot's position loop alone reaches its amplifiers' e-stop threshold
/// (../shared/reference/raven2-actuation.md §3-4: |dac| 20000 counts, 3695.8 counts per N m, KP
/// 0.30, 0.30, 0.15 N m per motor rad; 0.0073423 rad, 0.0082288 rad, 0.00046327 m of joint per
/// motor rad): 0.066 rad, 0.074 rad, 8.4 mm. None on the tool's joints, whose integrators wind
/// up whatever the lead.
raven::ArmJoints followingLimit();

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
