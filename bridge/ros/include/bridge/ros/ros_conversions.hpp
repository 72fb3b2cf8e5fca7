#pragma once
// Between the platform's SI values and the Raven-II's ROS messages: joint states, transforms,
// operating states and raven_state. Reading a message checks it and says what is wrong.
// Includes ROS 1 message headers: C++17 translation units only.

#include <crtk_msgs/OperatingState.h>
#include <crtk_msgs/StringStamped.h>
#include <crtk_msgs/operating_state.h>
#include <geometry_msgs/Pose.h>
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/Transform.h>
#include <geometry_msgs/TransformStamped.h>
#include <geometry_msgs/TwistStamped.h>
#include <geometry_msgs/WrenchStamped.h>
#include <raven_2/raven_state.h>
#include <raven_twin/GraspForces.h>
#include <sensor_msgs/JointState.h>

#include <optional>
#include <string>

#include "bridge/raven_platform.hpp"

namespace bridge::ros1 {

/// A value read from a message, or why it could not be.
template <typename T>
struct Parsed {
  std::optional<T> value;
  std::string error;

  static Parsed ok(T v) { return {std::move(v), {}}; }
  static Parsed fail(std::string why) { return {std::nullopt, std::move(why)}; }
};

/// One arm's joints from 7 values, or the paper's controller's 15 (7 used, then 8 that must be
/// 0). Every value must be finite. `field` names them in the error ("position", "jp").
Parsed<ArmJoints> armJointsFromValues(const std::vector<double>& values, const std::string& field);
/// One arm's joints from a command's `position`: 7 values, or the paper's controller's 15
/// (7 used, then 8 that must be 0). Every value must be finite.
Parsed<ArmJoints> armJointsFromCommand(const sensor_msgs::JointState& message);
/// A state command: "enable", "disable", "pause", "resume", "home" or "unhome".
Parsed<StateCommand> stateCommandFrom(const crtk_msgs::StringStamped& message);
/// A grasper command's value: position[0], finite.
Parsed<double> graspFromCommand(const sensor_msgs::JointState& message);
/// A rigid transform; the quaternion must be finite and of unit length (within 1e-3).
/// `zero_is_identity`: an all-zero quaternion (an unset field) means no rotation.
Parsed<Eigen::Isometry3d> poseFromTransform(const geometry_msgs::Transform& message,
                                            bool zero_is_identity = false);
/// The same from a geometry_msgs/Pose (standard CRTK's PoseStamped commands).
Parsed<Eigen::Isometry3d> poseFromPose(const geometry_msgs::Pose& message);

/// measured_js / setpoint_js of one arm: names "<colour>_shoulder", ..., SI units.
sensor_msgs::JointState toJointState(const JointSample& sample, std::string_view colour,
                                     ::ros::Time stamp);
/// The robot's 7 joints from a measured_js / setpoint_js (velocity and effort may be empty).
Parsed<JointSample> jointSampleFromState(const sensor_msgs::JointState& message);
/// graspN/measured_js: [jaw1 + jaw2, jaw1, jaw2].
sensor_msgs::JointState toGraspState(const JointSample& sample, std::string_view colour,
                                     ::ros::Time stamp);

/// <arm>/jaw/measured_js as the dVRK has it: one joint, "jaw", the opening jaw1 + jaw2.
sensor_msgs::JointState toJawState(const JointSample& sample, ::ros::Time stamp);

/// A pose as a geometry_msgs/Pose (AMBF's state messages carry their objects' poses so).
geometry_msgs::Pose toPose(const Eigen::Isometry3d& pose);
/// Standard CRTK's measured_cp / setpoint_cp.
geometry_msgs::PoseStamped toPoseStamped(const Eigen::Isometry3d& pose, ::ros::Time stamp,
                                         std::string frame);
geometry_msgs::TransformStamped toTransformStamped(const Eigen::Isometry3d& pose, ::ros::Time stamp,
                                                   std::string frame, std::string child_frame);

/// measured_cv as CRTK carries it: linear (m/s), then angular (rad/s) velocity, `frame` named.
geometry_msgs::TwistStamped toTwistStamped(const Eigen::Matrix<double, 6, 1>& twist,
                                           ::ros::Time stamp, std::string frame);
/// measured_cf as CRTK carries it: the grasper's total force and torque, `frame` named.
geometry_msgs::WrenchStamped toWrenchStamped(const GrasperForces& forces, ::ros::Time stamp,
                                             std::string frame);
/// Each jaw's normal and friction forces and contact count.
raven_twin::GraspForces toGraspForces(const GrasperForces& forces, ::ros::Time stamp,
                                      std::string frame);
/// A grasper's forces from the twin's jaw_forces and measured_cf messages; refused (with the
/// field named) when any value is not finite.
Parsed<GrasperForces> grasperForcesFrom(const raven_twin::GraspForces& jaws,
                                        const geometry_msgs::Wrench& wrench);

/// The robot's crtk_msgs/operating_state or standard CRTK's crtk_msgs/OperatingState (the same
/// fields and MD5 under two names).
template <typename Message = crtk_msgs::operating_state>
Message toOperatingState(const OperatingStatus& status, ::ros::Time stamp) {
  Message m;
  m.header.stamp = stamp;
  m.state = std::string(wireName(status.state));
  m.is_homed = status.is_homed;
  m.is_busy = status.is_busy;
  return m;
}
Parsed<OperatingStatus> operatingStatusFrom(const crtk_msgs::operating_state& message);

raven_2::raven_state toRavenState(const RavenStateSnapshot& state, ::ros::Time stamp);
RavenStateSnapshot ravenStateFrom(const raven_2::raven_state& message);

}  // namespace bridge::ros1
