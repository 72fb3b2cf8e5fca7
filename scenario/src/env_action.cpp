#include "scenario/env_action.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "twin/drive_train.hpp"
#include "twin/motor_controller.hpp"

namespace scenario {

controller::FollowingLimit followingLimit() {
  constexpr double kFree = std::numeric_limits<double>::infinity();
  // The robot's firmware constants, as the twin's motors run them (the same on both arms).
  const twin::MotorGains gains = twin::MotorGains::raven2(raven::Arm::Left);
  const twin::DacConversion dac = twin::DacConversion::raven2(raven::Arm::Left);
  const raven::ArmJoints transmission = twin::DriveTrain::raven2().transmission;
  controller::FollowingLimit limit;
  limit.give = gains.kp.cwiseProduct(transmission).cwiseInverse();
  for (int i = 0; i < raven::kJointCount; ++i) {
    const double half_of_overdrive = 0.5 * dac.overdrive / std::abs(dac.counts_per_torque(i));
    const bool integrates = gains.ki(i) > 0.0;
    limit.lead(i) = integrates ? kFree : half_of_overdrive * limit.give(i);
    // GRASP2's amplifier command is never checked (the robot's check stops before it): none.
    limit.torque(i) = integrates && i != raven::kJaw2 ? half_of_overdrive : kFree;
  }
  return limit;
}

controller::Arrival arrival() {
  controller::Arrival arrival;
  arrival.most_make_up = 0.002;
  return arrival;
}

EnvAction envActionNamed(std::string_view name) {
  if (name == "joints") return EnvAction::Joints;
  if (name == "joint_deltas") return EnvAction::JointDeltas;
  if (name == "tool_deltas") return EnvAction::ToolDeltas;
  throw std::invalid_argument("unknown action '" + std::string(name) +
                              "' (joints, joint_deltas or tool_deltas)");
}

int actionSize(EnvAction kind) {
  return kind == EnvAction::ToolDeltas ? 8 : 14;
}

ActionBounds actionBounds(EnvAction kind, const raven::JointLimits& limits) {
  ActionBounds b{Eigen::VectorXd(actionSize(kind)), Eigen::VectorXd(actionSize(kind))};
  // Element by element: GCC 12 misreads Eigen's packets over the 7-vectors here.
  for (Eigen::Index i = 0; i < b.low.size(); ++i) {
    const Eigen::Index joint = i % raven::kJointCount;
    switch (kind) {
      case EnvAction::Joints:
        b.low(i) = limits.low(joint);
        b.high(i) = limits.high(joint);
        break;
      case EnvAction::JointDeltas:  // at most a joint's range
        b.high(i) = limits.high(joint) - limits.low(joint);
        b.low(i) = -b.high(i);
        break;
      case EnvAction::ToolDeltas:  // per arm dx, dy, dz, then the jaws' opening
        if (i % 4 < 3) {
          b.low(i) = -kMaxToolDelta;
          b.high(i) = kMaxToolDelta;
        } else {
          b.low(i) = 0.0;
          b.high(i) = limits.high(raven::kJaw1) + limits.high(raven::kJaw2);
        }
        break;
    }
  }
  return b;
}

controller::ArmPair targetsOf(EnvAction kind, const Eigen::VectorXd& action,
                              const controller::ArmPair& current,
                              const raven::PerArm<raven::ArmKinematics>& kinematics,
                              const raven::ArmJoints& home) {
  if (action.size() != actionSize(kind)) {
    throw std::invalid_argument("an action has " + std::to_string(actionSize(kind)) +
                                " values, not " + std::to_string(action.size()));
  }
  for (Eigen::Index i = 0; i < action.size(); ++i) {
    if (!std::isfinite(action(i))) {
      throw std::invalid_argument("action[" + std::to_string(i) + "] is " +
                                  std::to_string(action(i)) + ": actions must be finite");
    }
  }
  const ActionBounds bounds = actionBounds(kind, kinematics[0].limits());
  const Eigen::VectorXd a = action.cwiseMax(bounds.low).cwiseMin(bounds.high);
  controller::ArmPair out = current;
  for (std::size_t arm = 0; arm < 2; ++arm) {
    const auto i = static_cast<Eigen::Index>(arm);
    switch (kind) {
      case EnvAction::Joints:
        out[arm] = a.segment<raven::kJointCount>(i * raven::kJointCount);
        break;
      case EnvAction::JointDeltas:
        out[arm] += a.segment<raven::kJointCount>(i * raven::kJointCount);
        break;
      case EnvAction::ToolDeltas: {
        // The wrist point moved until the tool tip lands where asked: with the wrist's joints
        // locked the tool turns a little as the arm moves, so the first guess is corrected.
        const raven::ArmKinematics& k = kinematics[arm];
        const Eigen::Vector3d goal = k.toolPose(current[arm]).translation() + a.segment<3>(i * 4);
        Eigen::Vector3d wrist = k.wristPoint(current[arm]) + a.segment<3>(i * 4);
        for (int pass = 0; pass < 4; ++pass) {
          const auto solved = k.inverseWristLocked(wrist, current[arm], home);
          if (!solved.ok || solved.clamp.any()) break;  // out of reach: the arm stays
          out[arm] = solved.joints;
          wrist += goal - k.toolPose(solved.joints).translation();
        }
        // The opening split as it is now: jaw1 - jaw2 (the grasper's turn) kept.
        const double turn = current[arm](raven::kJaw1) - current[arm](raven::kJaw2);
        out[arm](raven::kJaw1) = 0.5 * (a(i * 4 + 3) + turn);
        out[arm](raven::kJaw2) = 0.5 * (a(i * 4 + 3) - turn);
        break;
      }
    }
  }
  return out;
}

Eigen::VectorXd actionFor(EnvAction kind, const controller::ArmPair& targets,
                          const controller::ArmPair& current,
                          const raven::PerArm<raven::ArmKinematics>& kinematics) {
  Eigen::VectorXd out(actionSize(kind));
  for (std::size_t arm = 0; arm < 2; ++arm) {
    const auto i = static_cast<Eigen::Index>(arm);
    switch (kind) {
      case EnvAction::Joints:
        out.segment<raven::kJointCount>(i * raven::kJointCount) = targets[arm];
        break;
      case EnvAction::JointDeltas:
        out.segment<raven::kJointCount>(i * raven::kJointCount) = targets[arm] - current[arm];
        break;
      case EnvAction::ToolDeltas:
        out.segment<3>(i * 4) = kinematics[arm].toolPose(targets[arm]).translation() -
                                kinematics[arm].toolPose(current[arm]).translation();
        out(i * 4 + 3) = targets[arm](raven::kJaw1) + targets[arm](raven::kJaw2);
        break;
    }
  }
  return out;
}

}  // namespace scenario
