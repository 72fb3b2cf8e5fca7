#pragma once
// The peg transfer as a policy meets it on any Raven-II (the twin node over ROS, the physical
// robot): the robot under the controller a gamepad drives it with, the environment's
// observation from what the robot reports (the rings from a perception when there is one), and
// actions of PegTransferEnv's kinds reached as its waypoint steps are: clipped, clamped to the
// joint limits, under the velocity caps.

#include <Eigen/Core>
#include <optional>

#include "bridge/raven_platform.hpp"
#include "bridge/scene_perception.hpp"
#include "controller/dual_platform_controller.hpp"
#include "raven/platform_profile.hpp"
#include "scenario/env_action.hpp"
#include "scenario/peg_layout.hpp"

namespace scenario {

/// What one step did.
struct RobotStep {
  std::size_t refused = 0;  ///< commands the robot refused
  bool faulted = false;     ///< the robot is FAULT (e-stopped) after it
};

/// One robot, one episode at a time, on the robot's own clock.
class PegTransferRobot {
 public:
  /// `scene`: what sees the rings (the twin node's object topics, a tracker), or null. Both must
  /// outlive this.
  PegTransferRobot(bridge::RavenPlatform& robot, bridge::ScenePerception* scene,
                   EnvAction action = EnvAction::JointDeltas);

  /// Enables and homes the robot (within `timeout` s of its clock) and starts the controller
  /// from there. Throws std::runtime_error naming the state reached when it does not finish.
  void makeReady(double timeout);
  /// The observation (observation_layout.hpp); the rings' centres are NaN without a perception.
  Eigen::VectorXd observe();
  /// One waypoint step of `action` (PegTransferEnv::step's rules). Needs makeReady(). Throws
  /// std::invalid_argument for an action of the wrong size or with a value that is not finite.
  RobotStep step(const Eigen::VectorXd& action);
  /// Rings resting on their target posts as the perception sees them; none without one.
  std::optional<int> placed();
  double time() const { return robot_.now(); }
  int actionSize() const { return scenario::actionSize(action_); }

 private:
  controller::DualPlatformController& controller();

  bridge::RavenPlatform& robot_;
  bridge::ScenePerception* scene_;
  EnvAction action_;
  raven::PlatformProfile profile_;
  raven::PerArm<raven::ArmKinematics> kinematics_;
  PegLayout layout_;
  std::optional<controller::DualPlatformController> controller_;
};

}  // namespace scenario
