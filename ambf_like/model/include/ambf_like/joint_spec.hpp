#pragma once
// Plain description of one joint (constraint and controller) as written in an ADF or URDF file.

#include <array>
#include <optional>
#include <string>

#include "ambf_like/load_error.hpp"
#include "ambf_like/transform.hpp"

namespace ambf_like {

enum class JointType {
  Revolute,
  Continuous,
  Prismatic,
  Fixed,
  P2P,
  LinearSpring,
  TorsionSpring,
  ConeTwist,
  SixDof,
  SixDofSpring,
};

/// What the joint's PID output drives (AMBF's `controller output type`).
enum class ControlOutput { Effort, Velocity, Position };

/// PID gains of a joint controller.
struct PidGains {
  double p = 0.0;
  double i = 0.0;
  double d = 0.0;
};

/// Lower and upper bound of a single-axis joint (rad or m).
struct JointLimits {
  double low = 0.0;
  double high = 0.0;
};

/// Per-axis values for six-DoF joints: linear x, y, z then angular x, y, z.
using SixAxis = std::array<double, 6>;

/// Limits and springs of a six-DoF joint (AMBF defaults).
struct SixDofSpec {
  SixAxis low{-1.2, -1.2, -1.2, -1.2, -1.2, -1.2};
  SixAxis high{1.2, 1.2, 1.2, 1.2, 1.2, 1.2};
  SixAxis stiffness{1, 1, 1, 1, 1, 1};  ///< six dof spring only
  SixAxis damping{0.7, 0.7, 0.7, 0.7, 0.7, 0.7};
  SixAxis equilibrium{0, 0, 0, 0, 0, 0};
};

/// A joint between two bodies: frames, type, limits and controller.
struct JointSpec {
  std::string name;
  std::string parent;  ///< body name, without the "BODY " prefix
  std::string child;
  Vec3 parent_axis = Vec3::UnitZ();  ///< in the parent body frame
  Vec3 parent_pivot = Vec3::Zero();
  Vec3 child_axis = Vec3::UnitZ();  ///< in the child body frame
  Vec3 child_pivot = Vec3::Zero();
  JointType type = JointType::Revolute;
  std::optional<JointLimits> limits;      ///< single-axis joints; enabled only if both bounds given
  Vec3 cone_twist_limits{0.7, 0.7, 0.7};  ///< twist (x), swing 1 (y), swing 2 (z)
  SixDofSpec six_dof;
  double child_offset = 0.0;  ///< rotation of the child about the axis at zero position (rad)
  double joint_offset = 0.0;  ///< rotation of the joint's zero about the axis (rad)
  PidGains controller{10.0, 0.0, 1.0};
  ControlOutput output = ControlOutput::Velocity;
  double max_motor_impulse = 0.1;
  /// Speed limit of the joint's motor (rad/s or m/s), an ambf_like extension (`max velocity`):
  /// caps velocity commands and the speed a position servo may ask for. Empty: no cap.
  std::optional<double> max_velocity;
  double damping = 0.0;
  std::optional<double> stiffness;          ///< springs; empty: derived from the body masses
  std::optional<double> equilibrium_point;  ///< springs; empty: mid-range
  bool enable_motor = true;
  bool enable_feedback = false;
  double erp = 0.1;
  double cfm = 0.1;
  bool ignore_inter_collision = true;  ///< parent and child do not collide
  bool passive = false;                ///< excluded from the commanded/published joints
  SourceRef where;

  /// True for joints with one coordinate (revolute, continuous, prismatic, the two springs).
  bool isSingleAxis() const {
    return type == JointType::Revolute || type == JointType::Continuous ||
           type == JointType::Prismatic || type == JointType::LinearSpring ||
           type == JointType::TorsionSpring;
  }
  /// True for revolute, continuous and torsion-spring joints (coordinate in radians).
  bool isAngular() const {
    return type == JointType::Revolute || type == JointType::Continuous ||
           type == JointType::TorsionSpring;
  }
};

}  // namespace ambf_like
