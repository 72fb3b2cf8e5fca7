#include "crtk_face.hpp"

#include <crtk_msgs/QueryForwardKinematics.h>
#include <crtk_msgs/QueryInverseKinematics.h>

#include <stdexcept>

#include "bridge/ros/low_latency.hpp"
#include "bridge/ros/ros_conversions.hpp"

namespace bridge::ros1 {

namespace {

/// A move has arrived when its setpoint is the goal (a planned move ends exactly on it).
constexpr double kArrived = 1e-9;

/// The options, or why their topics would be the robot's own (ROS 1 carries one type per topic,
/// and a state command heard twice would be applied twice).
const CrtkFaceOptions& checked(const CrtkFaceOptions& options) {
  if (options.arm_names[0].empty() || options.arm_names[1].empty() ||
      options.arm_names[0] == options.arm_names[1]) {
    throw std::invalid_argument("the standard CRTK face needs two different, non-empty arm names");
  }
  if (!options.ros_namespace.empty()) return options;
  for (const std::string& name : options.arm_names) {
    for (Arm arm : raven::kArms) {
      if (name == armNamespace(arm) || name == graspNamespace(arm)) {
        throw std::invalid_argument("the standard CRTK face's arm '" + name +
                                    "' would take the robot's own /" + name +
                                    " topics: give the face a namespace (--crtk-namespace) or "
                                    "other arm names");
      }
    }
  }
  return options;
}

}  // namespace

CrtkFace::CrtkFace(RavenPlatform& platform, ::ros::NodeHandle& node, const CrtkFaceOptions& options,
                   CommandInbox& inbox)
    : platform_(platform),
      node_(node),
      options_(checked(options)),
      inbox_(inbox),
      kinematics_{
          raven::ArmKinematics(options.profile.reportingArm(Arm::Left), options.profile.limits),
          raven::ArmKinematics(options.profile.reportingArm(Arm::Right), options.profile.limits)} {
  for (Arm arm : raven::kArms) {
    advertise(arm);
    subscribeCommands(arm);
    advertiseQueries(arm);
  }
  publishOperatingStates(inbox_.stamp());
}

std::string CrtkFace::topic(Arm arm, std::string_view relative) const {
  const std::string& ns = options_.ros_namespace;
  return (ns.empty() ? "" : ns + "/") + options_.arm_names[slot(arm)] + "/" + std::string(relative);
}

void CrtkFace::advertise(Arm arm) {
  ArmPublishers& p = publishers_[slot(arm)];
  constexpr std::uint32_t kQueue = 1000;  // lock-step bursts: a subscriber sees every cycle
  p.operating_state = node_.advertise<crtk_msgs::OperatingState>(topic(arm, "operating_state"), 10,
                                                                 /*latch=*/true);
  p.measured_js = node_.advertise<sensor_msgs::JointState>(topic(arm, "measured_js"), kQueue);
  p.setpoint_js = node_.advertise<sensor_msgs::JointState>(topic(arm, "setpoint_js"), kQueue);
  p.measured_cp = node_.advertise<geometry_msgs::PoseStamped>(topic(arm, "measured_cp"), kQueue);
  p.setpoint_cp = node_.advertise<geometry_msgs::PoseStamped>(topic(arm, "setpoint_cp"), kQueue);
  p.measured_cv = node_.advertise<geometry_msgs::TwistStamped>(topic(arm, "measured_cv"), kQueue);
  if (platform_.measuredCf(arm)) {  // a platform that senses forces (the twin)
    p.measured_cf =
        node_.advertise<geometry_msgs::WrenchStamped>(topic(arm, "measured_cf"), kQueue);
  }
  p.jaw_measured_js =
      node_.advertise<sensor_msgs::JointState>(topic(arm, "jaw/measured_js"), kQueue);
  p.jaw_setpoint_js =
      node_.advertise<sensor_msgs::JointState>(topic(arm, "jaw/setpoint_js"), kQueue);
}

template <typename Message>
void CrtkFace::subscribe(Arm arm, CrtkCommand command,
                         std::function<ReadCommand(const Message&)> read) {
  const std::uint8_t id = lockStepId(command, arm);
  const std::string name = topic(arm, relativeName(command));
  inbox_.expect(id, name);
  constexpr std::uint32_t kCommandQueue = 10000;  // never drop a command
  subscribers_.push_back(node_.subscribe<Message>(
      name, kCommandQueue,
      [this, id, read](const typename Message::ConstPtr& message) {
        inbox_.receive(id, [this, id, command = read(*message)] {
          if (!command.error.empty()) {
            inbox_.refuse(id, command.error);
          } else if (const CommandResult result = command.action(); !result) {
            inbox_.reportRefusal(id, result.note);  // what refused it logged it
          }
          publishOperatingStates(inbox_.stamp());  // a move's busy flag rises now
        });
      },
      {}, lowLatency()));
}

void CrtkFace::subscribeCommands(Arm arm) {
  using sensor_msgs::JointState;
  using Pose = geometry_msgs::PoseStamped;
  using Command = CrtkCommand;
  subscribe<crtk_msgs::StringStamped>(arm, Command::StateCommand, [this](const auto& m) {
    return later(stateCommandFrom(m), [this](StateCommand c) { return platform_.send(c); });
  });
  subscribe<JointState>(arm, Command::ServoJp, [this, arm](const JointState& m) {
    return later(armJointsFromCommand(m), [this, arm](const ArmJoints& q) {
      return sendMotion(ServoJp{arm, q}, arm);
    });
  });
  subscribe<JointState>(arm, Command::ServoJr, [this, arm](const JointState& m) {
    return later(armJointsFromCommand(m), [this, arm](const ArmJoints& q) {
      return sendMotion(ServoJr{arm, q}, arm);
    });
  });
  subscribe<Pose>(arm, Command::ServoCp, [this, arm](const Pose& m) {
    return later(poseFromPose(m.pose), [this, arm](const Eigen::Isometry3d& p) {
      return sendMotion(ServoCp{arm, p}, arm);
    });
  });
  subscribe<Pose>(arm, Command::ServoCr, [this, arm](const Pose& m) {
    return later(poseFromPose(m.pose), [this, arm](const Eigen::Isometry3d& p) {
      return sendMotion(ServoCr{arm, p}, arm);
    });
  });
  subscribe<JointState>(arm, Command::JawServoJp, [this, arm](const JointState& m) {
    return later(graspFromCommand(m), [this, arm](double o) {
      return sendMotion(ServoJawJp{arm, o}, arm);
    });
  });
  subscribe<JointState>(arm, Command::JawServoJr, [this, arm](const JointState& m) {
    return later(graspFromCommand(m), [this, arm](double o) {
      return sendMotion(ServoJawJr{arm, o}, arm);
    });
  });
  // Moves are resolved when they run: move_cp and the jaw's move_jp start from the setpoint then.
  subscribe<JointState>(arm, Command::MoveJp, [this, arm](const JointState& m) {
    return later(armJointsFromCommand(m),
                 [this, arm](const ArmJoints& q) { return startMove(arm, q); });
  });
  subscribe<Pose>(arm, Command::MoveCp, [this, arm](const Pose& m) {
    return later(poseFromPose(m.pose),
                 [this, arm](const Eigen::Isometry3d& pose) { return moveToPose(arm, pose); });
  });
  subscribe<JointState>(arm, Command::JawMoveJp, [this, arm](const JointState& m) {
    return later(graspFromCommand(m), [this, arm](double opening) {
      return startMove(arm, raven::withJawOpening(platform_.setpointJs(arm).position, opening));
    });
  });
}

void CrtkFace::advertiseQueries(Arm arm) {
  using Fk = crtk_msgs::QueryForwardKinematics;
  using Ik = crtk_msgs::QueryInverseKinematics;
  const raven::ArmKinematics& kinematics = kinematics_[slot(arm)];
  const boost::function<bool(Fk::Request&, Fk::Response&)> forward =
      [&kinematics](Fk::Request& request, Fk::Response& response) {
        const auto q = armJointsFromValues(request.jp, "jp");
        response.result = q.value.has_value();
        response.message = q.error;
        if (q.value) response.cp = toPose(kinematics.toolPose(*q.value));
        return true;
      };
  const boost::function<bool(Ik::Request&, Ik::Response&)> inverse =
      [this, arm](Ik::Request& request, Ik::Response& response) {
        const auto pose = poseFromPose(request.cp);
        // The reference joints choose among the solutions; none given: the arm's setpoint.
        const auto near = request.jp.empty()
                              ? Parsed<ArmJoints>::ok(platform_.setpointJs(arm).position)
                              : armJointsFromValues(request.jp, "jp");
        response.result = false;
        response.message = !pose.value ? "cp: " + pose.error : near.error;
        if (!pose.value || !near.value) return true;
        const auto solution = inverseNear(arm, *pose.value, *near.value);
        response.result = solution.ok;
        response.message = solution.ok ? (solution.clamp.any() ? "clamped to the joint limits" : "")
                                       : "no inverse-kinematics solution near jp";
        if (solution.ok) response.jp.assign(solution.joints.data(), solution.joints.data() + 7);
        return true;
      };
  // CRTK's names, and the ones crtk_python_client's forward_kinematics() and
  // inverse_kinematics() call.
  for (const char* name : {"query_cp", "forward_kinematics"}) {
    services_.push_back(node_.advertiseService(topic(arm, name), forward));
  }
  for (const char* name : {"query_jp", "inverse_kinematics"}) {
    services_.push_back(node_.advertiseService(topic(arm, name), inverse));
  }
}

CommandResult CrtkFace::sendMotion(const PlatformCommand& command, Arm arm) {
  CommandResult result = platform_.send(command);
  if (result) moving_to_[slot(arm)].reset();  // a servo command pre-empts the move
  return result;
}

CommandResult CrtkFace::startMove(Arm arm, const ArmJoints& goal) {
  CommandResult result = platform_.send(MoveJp{arm, goal});
  if (result) {
    ArmJoints end = goal;  // the move ends on the goal saturated to the limits, as the robot's
    kinematics_[slot(arm)].clamp(end);
    moving_to_[slot(arm)] = end;
  }
  return result;
}

raven::IkSolution CrtkFace::inverseNear(Arm arm, const Eigen::Isometry3d& pose,
                                        const ArmJoints& near) const {
  return kinematics_[slot(arm)].inverse(pose, near(raven::kJaw1) + near(raven::kJaw2), near);
}

CommandResult CrtkFace::moveToPose(Arm arm, const Eigen::Isometry3d& pose) {
  const auto solution = inverseNear(arm, pose, platform_.setpointJs(arm).position);
  if (solution.ok) return startMove(arm, solution.joints);
  const std::string why = "no inverse-kinematics solution near the current joints; nothing moved";
  log_.warn(why, "refused move_cp " + std::string(raven::armName(arm)) + ": " + why,
            platform_.now());
  return CommandResult::refused(why);
}

OperatingStatus CrtkFace::armStatus(Arm arm) const {
  OperatingStatus status = platform_.operatingStatus();
  const bool homing = status.is_busy && !status.is_homed;
  status.is_busy = homing || (status.is_busy && moving_to_[slot(arm)].has_value());
  return status;
}

void CrtkFace::publishOperatingStates(::ros::Time stamp) {
  for (Arm arm : raven::kArms) {
    const OperatingStatus status = armStatus(arm);
    auto& published = published_status_[slot(arm)];
    if (published && *published == status) continue;
    publishers_[slot(arm)].operating_state.publish(
        toOperatingState<crtk_msgs::OperatingState>(status, stamp));
    published = status;
  }
}

void CrtkFace::publishState(::ros::Time stamp) {
  const bool busy = platform_.operatingStatus().is_busy;
  for (Arm arm : raven::kArms) {
    auto& goal = moving_to_[slot(arm)];
    if (goal &&
        (!busy || (platform_.setpointJs(arm).position - *goal).cwiseAbs().maxCoeff() < kArrived)) {
      goal.reset();
    }
    publishArmState(arm, stamp);
  }
  publishOperatingStates(stamp);
}

void CrtkFace::publishArmState(Arm arm, ::ros::Time stamp) {
  // Every cycle: build only what someone subscribes to.
  ArmPublishers& p = publishers_[slot(arm)];
  const std::string_view colour = armColour(arm);
  const std::string base = std::string(colour) + "_base";
  auto wanted = [](const ::ros::Publisher& publisher) {
    return publisher && publisher.getNumSubscribers() > 0;
  };
  if (wanted(p.measured_js) || wanted(p.jaw_measured_js) || wanted(p.measured_cv)) {
    const JointSample measured = platform_.measuredJs(arm);
    if (wanted(p.measured_js)) p.measured_js.publish(toJointState(measured, colour, stamp));
    if (wanted(p.jaw_measured_js)) p.jaw_measured_js.publish(toJawState(measured, stamp));
    if (wanted(p.measured_cv)) {
      const auto twist = kinematics_[slot(arm)].toolTwist(measured.position, measured.velocity);
      p.measured_cv.publish(toTwistStamped(twist, stamp, base));
    }
  }
  if (wanted(p.setpoint_js) || wanted(p.jaw_setpoint_js)) {
    const JointSample setpoint = platform_.setpointJs(arm);
    if (wanted(p.setpoint_js)) p.setpoint_js.publish(toJointState(setpoint, colour, stamp));
    if (wanted(p.jaw_setpoint_js)) p.jaw_setpoint_js.publish(toJawState(setpoint, stamp));
  }
  if (wanted(p.measured_cp)) {
    p.measured_cp.publish(toPoseStamped(platform_.measuredCp(arm).pose, stamp, base));
  }
  if (wanted(p.setpoint_cp)) {
    p.setpoint_cp.publish(toPoseStamped(platform_.setpointCp(arm).pose, stamp, base));
  }
  if (wanted(p.measured_cf)) {
    if (const auto forces = platform_.measuredCf(arm)) {
      p.measured_cf.publish(toWrenchStamped(*forces, stamp, "world"));
    }
  }
}

}  // namespace bridge::ros1
