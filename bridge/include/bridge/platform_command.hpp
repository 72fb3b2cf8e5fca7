#pragma once
// The command objects every RavenPlatform takes: the same values reach the in-process twin, the
// twin over ROS and the physical robot. SI units, per-arm joint order of raven::ArmJoints.

#include <Eigen/Geometry>
#include <string>
#include <variant>

#include "bridge/operating_state.hpp"
#include "raven/arm.hpp"

namespace bridge {

using raven::Arm;
using raven::ArmJoints;

/// Absolute joint positions (CRTK servo_jp).
struct ServoJp {
  Arm arm;
  ArmJoints position;
};

/// Joint increments (CRTK servo_jr): added to what is still pending, then consumed within the
/// robot's per-cycle clamps.
struct ServoJr {
  Arm arm;
  ArmJoints increment;
};

/// A joint goal reached along a planned trajectory (CRTK move_jp); the platform is busy until
/// the arm arrives.
struct MoveJp {
  Arm arm;
  ArmJoints goal;
};

/// An absolute tool pose in the platform's reporting frame (CRTK servo_cp).
struct ServoCp {
  Arm arm;
  Eigen::Isometry3d pose;
};

/// A tool-pose increment (CRTK servo_cr, the Raven's raven_automove): the translation is added
/// to the pending goal's position and the rotation pre-multiplied onto its orientation.
struct ServoCr {
  Arm arm;
  Eigen::Isometry3d increment;
};

/// An absolute grasper opening, jaw1 + jaw2 in rad (CRTK graspN/servo_jp); the jaws' difference
/// (the grasper's orientation) is kept.
struct ServoJawJp {
  Arm arm;
  double opening;
};

/// A grasper-opening increment (CRTK graspN/servo_jr).
struct ServoJawJr {
  Arm arm;
  double increment;
};

using PlatformCommand =
    std::variant<StateCommand, ServoJp, ServoJr, MoveJp, ServoCp, ServoCr, ServoJawJp, ServoJawJr>;

/// "servo_jr left", "state_command enable", ...: for logs and refusals.
std::string describe(const PlatformCommand& command);

}  // namespace bridge
