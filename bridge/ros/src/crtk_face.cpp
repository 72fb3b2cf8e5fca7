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

}  // namespace

namespace {

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
            inbox_.refuse(id, result.note);
          }
          publishOperatingStates(inbox_.stamp());  // a move's busy flag rises now
        });
      },
      {}, lowLatency()));
}

void CrtkFace::subscribeCommands(Arm arm) {
  using sensor_msgs::JointState;
  using Pose = geometry_msgs::PoseStamped;
  // A message read into a platform command: `make` turns the parsed value into the command.
  auto platformCommand = [this, arm](const auto& parsed, auto make) {
    if (!parsed.value) return ReadCommand{{}, parsed.error};
    return ReadCommand{[this, arm, command = PlatformCommand(make(*parsed.value))] {
                         return sendMotion(command, arm);
                       },
                       {}};
  };
  subscribe<crtk_msgs::StringStamped>(
      arm, CrtkCommand::StateCommand, [this](const crtk_msgs::StringStamped& m) {
        const auto parsed = stateCommandFrom(m);
        if (!parsed.value) return ReadCommand{{}, parsed.error};
        return ReadCommand{[this, c = *parsed.value] { return platform_.send(c); }, {}};
      });
  subscribe<JointState>(arm, CrtkCommand::ServoJp, [platformCommand, arm](const JointState& m) {
    return platformCommand(armJointsFromCommand(m), [arm](auto q) { return ServoJp{arm, q}; });
  });
  subscribe<JointState>(arm, CrtkCommand::ServoJr, [platformCommand, arm](const JointState& m) {
    return platformCommand(armJointsFromCommand(m), [arm](auto q) { return ServoJr{arm, q}; });
  });
  subscribe<Pose>(arm, CrtkCommand::ServoCp, [platformCommand, arm](const Pose& m) {
    return platformCommand(poseFromPose(m.pose), [arm](auto p) { return ServoCp{arm, p}; });
  });
  subscribe<Pose>(arm, CrtkCommand::ServoCr, [platformCommand, arm](const Pose& m) {
    return platformCommand(poseFromPose(m.pose), [arm](auto p) { return ServoCr{arm, p}; });
  });
  subscribe<JointState>(arm, CrtkCommand::JawServoJp, [platformCommand, arm](const JointState& m) {
    return platformCommand(graspFromCommand(m), [arm](double o) { return ServoJawJp{arm, o}; });
  });
  subscribe<JointState>(arm, CrtkCommand::JawServoJr, [platformCommand, arm](const JointState& m) {
    return platformCommand(graspFromCommand(m), [arm](double o) { return ServoJawJr{arm, o}; });
  });
  // Moves are resolved when they run: move_cp and the jaw's move_jp start from the setpoint then.
  subscribe<JointState>(arm, CrtkCommand::MoveJp, [this, arm](const JointState& m) {
    const auto goal = armJointsFromCommand(m);
    if (!goal.value) return ReadCommand{{}, goal.error};
    return ReadCommand{[this, arm, q = *goal.value] { return startMove(arm, q); }, {}};
  });
  subscribe<Pose>(arm, CrtkCommand::MoveCp, [this, arm](const Pose& m) {
    const auto goal = poseFromPose(m.pose);
    if (!goal.value) return ReadCommand{{}, goal.error};
    return ReadCommand{[this, arm, pose = *goal.value] {
                         const ArmJoints from = platform_.setpointJs(arm).position;
                         const double opening = from(raven::kJaw1) + from(raven::kJaw2);
                         const auto solution = kinematics_[slot(arm)].inverse(pose, opening, from);
                         if (!solution.ok) {
                           return CommandResult::refused(
                               "no inverse-kinematics solution near the current joints; nothing "
                               "moved");
                         }
                         return startMove(arm, solution.joints);
                       },
                       {}};
  });
  subscribe<JointState>(arm, CrtkCommand::JawMoveJp, [this, arm](const JointState& m) {
    const auto opening = graspFromCommand(m);
    if (!opening.value) return ReadCommand{{}, opening.error};
    return ReadCommand{[this, arm, o = *opening.value] {
                         return startMove(
                             arm, raven::withJawOpening(platform_.setpointJs(arm).position, o));
                       },
                       {}};
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
      [this, arm, &kinematics](Ik::Request& request, Ik::Response& response) {
        const auto pose = poseFromPose(request.cp);
        // The reference joints choose among the solutions; none given: the arm's setpoint.
        const auto near = request.jp.empty()
                              ? Parsed<ArmJoints>::ok(platform_.setpointJs(arm).position)
                              : armJointsFromValues(request.jp, "jp");
        response.result = false;
        response.message = !pose.value ? "cp: " + pose.error : near.error;
        if (!pose.value || !near.value) return true;
        const ArmJoints& from = *near.value;
        const auto solution =
            kinematics.inverse(*pose.value, from(raven::kJaw1) + from(raven::kJaw2), from);
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
    const raven::JointLimits& limits = options_.profile.limits;
    moving_to_[slot(arm)] = goal.cwiseMax(limits.low).cwiseMin(limits.high);
  }
  return result;
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
  ArmPublishers& p = publishers_[slot(arm)];
  const std::string_view colour = armColour(arm);
  auto wanted = [](const ::ros::Publisher& publisher) {
    return publisher && publisher.getNumSubscribers() > 0;
  };
  if (wanted(p.measured_js) || wanted(p.jaw_measured_js) || wanted(p.measured_cv)) {
    const JointSample measured = platform_.measuredJs(arm);
    p.measured_js.publish(toJointState(measured, colour, stamp));
    p.jaw_measured_js.publish(toJawState(measured, stamp));
    const auto twist = kinematics_[slot(arm)].toolTwist(measured.position, measured.velocity);
    p.measured_cv.publish(toTwistStamped(twist, stamp, std::string(colour) + "_base"));
  }
  if (wanted(p.setpoint_js) || wanted(p.jaw_setpoint_js)) {
    const JointSample setpoint = platform_.setpointJs(arm);
    p.setpoint_js.publish(toJointState(setpoint, colour, stamp));
    p.jaw_setpoint_js.publish(toJawState(setpoint, stamp));
  }
  const std::string base = std::string(colour) + "_base";
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
