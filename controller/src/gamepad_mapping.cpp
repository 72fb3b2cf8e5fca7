#include "controller/gamepad_mapping.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace controller {

MappingScheme mappingSchemeNamed(std::string_view name) {
  if (name == "m2") return MappingScheme::M2;
  if (name == "m1-left") return MappingScheme::M1Left;
  if (name == "m1-right") return MappingScheme::M1Right;
  throw std::invalid_argument("unknown mapping scheme '" + std::string(name) +
                              "' (m2, m1-left or m1-right)");
}

GamepadMapping::GamepadMapping(const raven::PlatformProfile& profile, MappingScheme scheme,
                               const ArmPair& joints, MappingConstants constants)
    : profile_(profile),
      kinematics_{raven::ArmKinematics::of(profile, Arm::Left),
                  raven::ArmKinematics::of(profile, Arm::Right)},
      constants_(constants),
      scheme_(scheme),
      joints_(joints) {
  reset(joints);
}

void GamepadMapping::reset(const ArmPair& joints) {
  joints_ = joints;
  for (Arm arm : raven::kArms) {
    const ArmJoints& q = joints[slot(arm)];
    ArmTarget& t = targets_[slot(arm)];
    t.wrist_point = kinematics_[slot(arm)].wristPoint(q);
    t.tool = kinematics_[slot(arm)].toolPose(q);
    t.roll = q(raven::kRoll);
    t.wrist = q(raven::kWrist);
    t.jaw_difference = q(raven::kJaw1) - q(raven::kJaw2);
    t.grasp = q(raven::kJaw1) + q(raven::kJaw2);
  }
}

bool GamepadMapping::outsideDeadzone(double x, double y) const {
  const double across = constants_.deadzone_reads_y_twice ? y : x;
  return std::sqrt(across * across + y * y) > constants_.deadzone;
}

void GamepadMapping::selectScheme(const recording::GamepadState& pad) {
  if (pad.back && pad.start) {
    scheme_ = MappingScheme::M2;
  } else if (pad.back) {
    scheme_ = MappingScheme::M1Left;
  } else if (pad.start) {
    scheme_ = MappingScheme::M1Right;
  }
}

void GamepadMapping::translate(Arm arm, double x, double y, bool bumper) {
  if (!outsideDeadzone(x, y)) return;
  Eigen::Vector3d step = Eigen::Vector3d::Zero();
  if (bumper) {
    step.z() = -y / constants_.divisor;
  } else {
    step.x() = x / constants_.divisor;
    step.y() = -y / constants_.divisor;
  }
  ArmTarget& t = targets_[slot(arm)];
  t.wrist_point += step;  // in the base frame {B}, open loop
  t.tool.translation() += step;
}

void GamepadMapping::turnWrist(Arm arm, double rx, double ry) {
  ArmTarget& t = targets_[slot(arm)];
  // An increment that would reach the joint's range is skipped, not clamped.
  auto turn = [](double& joint, double increment, double range) {
    if (std::abs(joint + increment) < range) joint += increment;
  };
  if (std::abs(rx) > constants_.deadzone) {
    turn(t.roll, -rx / constants_.wrist_divisor, constants_.roll_range);
  }
  if (std::abs(ry) > constants_.deadzone) {
    turn(t.wrist, ry / constants_.wrist_divisor, constants_.wrist_range);
  }
}

bool GamepadMapping::solve(Arm arm, IkMode mode, MappingResult& result) {
  const ArmTarget t = targets_[slot(arm)];
  const auto& kin = kinematics_[slot(arm)];
  ArmJoints current = joints_[slot(arm)];
  current(raven::kRoll) = t.roll;
  current(raven::kWrist) = t.wrist;
  const raven::IkSolution solution =
      mode == IkMode::WristLocked ? kin.inverseWristLocked(t.wrist_point, current, profile_.home)
                                  : kin.inverse(t.tool, t.grasp, current);
  if (!solution.ok) {  // keep the previous joints, and targets that match them
    result.unreachable[slot(arm)] = true;
    targets_[slot(arm)].wrist_point = kin.wristPoint(joints_[slot(arm)]);
    targets_[slot(arm)].tool = kin.toolPose(joints_[slot(arm)]);
    return false;
  }
  ArmJoints q = solution.joints;
  if (mode == IkMode::WristLocked) {  // the jaws: the grasp, about the kept orientation
    q(raven::kJaw1) = 0.5 * (t.grasp + t.jaw_difference);
    q(raven::kJaw2) = 0.5 * (t.grasp - t.jaw_difference);
  }
  const raven::ClampReport clamp = kin.clamp(q);
  result.clamped = result.clamped || clamp.any() || solution.clamp.any();
  joints_[slot(arm)] = q;
  return true;
}

MappingResult GamepadMapping::apply(const recording::GamepadState& pad, const ArmPair& measured) {
  selectScheme(pad);
  if (pad.a) {
    ik_mode_ = IkMode::WristLocked;
    reset(measured);
  } else if (pad.b && ik_mode_ != IkMode::Full) {
    ik_mode_ = IkMode::Full;
    for (Arm arm : raven::kArms) {
      targets_[slot(arm)].tool = kinematics_[slot(arm)].toolPose(joints_[slot(arm)]);
    }
  }
  for (auto [pressed, arm] : {std::pair{pad.x, Arm::Left}, std::pair{pad.y, Arm::Right}}) {
    if (!pressed) continue;  // the wrist back to its home values
    ArmTarget& t = targets_[slot(arm)];
    t.roll = profile_.home(raven::kRoll);
    t.wrist = profile_.home(raven::kWrist);
    t.jaw_difference = profile_.home(raven::kJaw1) - profile_.home(raven::kJaw2);
  }

  auto grasp = [&](double trigger) { return 1.0 - trigger / constants_.trigger_full; };
  MappingResult result;
  if (scheme_ == MappingScheme::M2) {
    translate(Arm::Left, pad.left_x, pad.left_y, pad.left_bumper);
    translate(Arm::Right, pad.right_x, pad.right_y, pad.right_bumper);
    targets_[slot(Arm::Left)].grasp = grasp(pad.left_trigger);
    targets_[slot(Arm::Right)].grasp = grasp(pad.right_trigger);
    for (Arm arm : raven::kArms) solve(arm, ik_mode_, result);
  } else {
    const Arm arm = scheme_ == MappingScheme::M1Left ? Arm::Left : Arm::Right;
    translate(arm, pad.left_x, pad.left_y, pad.left_bumper);
    targets_[slot(arm)].grasp = grasp(pad.right_trigger);
    turnWrist(arm, pad.right_x, pad.right_y);
    // Only the selected arm is planned: the other arm's joints stay exactly as they were (its
    // stored values, e.g. a wrist reset, take effect when it is next driven).
    solve(arm, IkMode::WristLocked, result);  // M1 always places the wrist point
  }
  result.joints = joints_;
  return result;
}

}  // namespace controller
