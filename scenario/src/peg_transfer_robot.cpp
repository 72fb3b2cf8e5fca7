#include "scenario/peg_transfer_robot.hpp"

#include <limits>
#include <stdexcept>

#include "bridge/enable_and_home.hpp"
#include "scenario/observation_layout.hpp"
#include "scenario/robot_observation.hpp"

namespace scenario {

PegTransferRobot::PegTransferRobot(bridge::RavenPlatform& robot, bridge::ScenePerception* scene,
                                   EnvAction action)
    : robot_(robot),
      scene_(scene),
      action_(action),
      profile_(raven::builtinProfile("physical")),
      kinematics_{raven::ArmKinematics::of(profile_, raven::Arm::Left),
                  raven::ArmKinematics::of(profile_, raven::Arm::Right)} {}

void PegTransferRobot::makeReady(double timeout) {
  try {
    bridge::enableAndHome(robot_, timeout);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(std::string("the robot ") + e.what());
  }
  controller::ControllerOptions control;
  control.following_limit = followingLimit();
  control.arrival = arrival();
  controller_.emplace(
      std::vector<controller::PlatformSlot>{{"robot", &robot_, controller::CommandStyle::ServoJr}},
      control);
  controller_->readPose();
}

controller::DualPlatformController& PegTransferRobot::controller() {
  if (!controller_) throw std::logic_error("the robot needs makeReady() before it steps");
  return *controller_;
}

Eigen::VectorXd PegTransferRobot::observe() {
  namespace obs = observation;
  Eigen::VectorXd o(obs::kSize);
  observeRobot(robot_, controller().commanded(), o);
  if (scene_) scene_->update(robot_.now());
  for (std::size_t i = 0; i < layout_.jobs.size(); ++i) {
    o.segment<obs::kRings.item_size>(obs::item(obs::kRings, i).start) =
        scene_ ? Eigen::Vector3d(scene_->sight(layout_.jobs[i].ring).pose.translation())
               : Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  }
  return o;
}

RobotStep PegTransferRobot::step(const Eigen::VectorXd& action) {
  controller::DualPlatformController& c = controller();
  const controller::ArmPair next =
      targetsOf(action_, action, c.commanded(), kinematics_, profile_.home);
  RobotStep out;
  out.refused = c.moveTo(next).refused;
  out.faulted = robot_.operatingStatus().state == bridge::OperatingState::Fault;
  return out;
}

std::optional<int> PegTransferRobot::placed() {
  if (!scene_) return std::nullopt;
  scene_->update(robot_.now());
  return ringsPlaced(*scene_, layout_);
}

}  // namespace scenario
