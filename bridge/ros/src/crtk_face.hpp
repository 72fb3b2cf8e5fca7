#pragma once
// The standard CRTK face of a served platform (CrtkFaceOptions): per arm, standard CRTK's state
// topics, commands and kinematics queries, over the same platform and the same checks as the
// robot's own topics. Includes ROS headers: C++17 only.

#include <ros/ros.h>

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "bridge/raven_platform.hpp"
#include "bridge/ros/command_topics.hpp"
#include "bridge/ros/raven_ros_server.hpp"
#include "bridge/ros/ros_conversions.hpp"
#include "bridge/throttled_log.hpp"
#include "command_inbox.hpp"
#include "raven/arm_kinematics.hpp"

namespace bridge::ros1 {

/// One CRTK namespace per arm (the jaw under its `jaw/`), on the server's node and queue.
class CrtkFace {
 public:
  CrtkFace(RavenPlatform& platform, ::ros::NodeHandle& node, const CrtkFaceOptions& options,
           CommandInbox& inbox);

  /// After every cycle: each arm's state topics, and operating_state where it changed.
  void publishState(::ros::Time stamp);

 private:
  /// A command read from its message, to run when the inbox says; or why it cannot be.
  using Action = std::function<CommandResult()>;
  struct ReadCommand {
    Action action;
    std::string error;
  };

  /// `parsed`'s error, or `run(value)` for when the inbox says.
  template <typename Value, typename Run>
  static ReadCommand later(const Parsed<Value>& parsed, Run run) {
    if (!parsed.value) return {{}, parsed.error};
    return {[run, value = *parsed.value] { return run(value); }, {}};
  }

  /// One arm's state publishers.
  struct ArmPublishers {
    ::ros::Publisher operating_state, measured_js, setpoint_js, measured_cp, setpoint_cp,
        measured_cv, measured_cf, jaw_measured_js, jaw_setpoint_js;
  };

  std::string topic(Arm arm, std::string_view relative) const;
  void advertise(Arm arm);
  void subscribeCommands(Arm arm);
  template <typename Message>
  void subscribe(Arm arm, CrtkCommand command, std::function<ReadCommand(const Message&)> read);
  void advertiseQueries(Arm arm);

  /// Sends a motion command of `arm`; a taken one ends the move the face was waiting on.
  CommandResult sendMotion(const PlatformCommand& command, Arm arm);
  /// Sends a move to `goal` and waits on it: the arm is busy until its setpoint arrives.
  CommandResult startMove(Arm arm, const ArmJoints& goal);
  /// move_cp: the pose's joints nearest the setpoint, then a move there; refused (and logged)
  /// without a solution.
  CommandResult moveToPose(Arm arm, const Eigen::Isometry3d& pose);
  /// The arm's inverse kinematics, keeping the opening of `near` and choosing the solution
  /// nearest it.
  raven::IkSolution inverseNear(Arm arm, const Eigen::Isometry3d& pose,
                                const ArmJoints& near) const;
  /// The robot's operating state as one arm sees it: busy while homing or while its own move runs.
  OperatingStatus armStatus(Arm arm) const;
  /// Publishes operating_state of each arm whose status differs from the last one published.
  void publishOperatingStates(::ros::Time stamp);
  void publishArmState(Arm arm, ::ros::Time stamp);

  RavenPlatform& platform_;
  ::ros::NodeHandle& node_;
  CrtkFaceOptions options_;
  CommandInbox& inbox_;
  raven::PerArm<raven::ArmKinematics> kinematics_;
  raven::PerArm<ArmPublishers> publishers_;
  std::vector<::ros::Subscriber> subscribers_;
  std::vector<::ros::ServiceServer> services_;
  /// Where each arm's move (move_jp, move_cp, jaw/move_jp) ends, while it runs.
  raven::PerArm<std::optional<ArmJoints>> moving_to_;
  raven::PerArm<std::optional<OperatingStatus>> published_status_;
  ThrottledLog log_;
};

}  // namespace bridge::ros1
