#include "bridge/ros/raven_ros_server.hpp"

#include <crtk_msgs/StringStamped.h>
#include <raven_2/raven_automove.h>
#include <raven_twin/Step.h>
#include <raven_twin/StepDone.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <spdlog/spdlog.h>
#include <std_msgs/String.h>

#include <algorithm>
#include <array>
#include <deque>
#include <optional>
#include <vector>

#include "bridge/ros/command_topics.hpp"
#include "bridge/ros/low_latency.hpp"
#include "bridge/ros/ros_conversions.hpp"
#include "bridge/throttled_log.hpp"
#include "command_inbox.hpp"
#include "crtk_face.hpp"
#include "raven/control_cycle.hpp"

namespace bridge::ros1 {

/// One command topic's message, read and checked: the commands it carries or why it is refused.
struct IncomingCommand {
  std::vector<PlatformCommand> commands;
  std::string error;
};

namespace {

constexpr double kMicron = 1e-6;
constexpr std::uint64_t kJointStatesEvery = 30;  // about 33 Hz, as upstream throttles it

template <typename Command, typename Value>
IncomingCommand fromParsed(const Parsed<Value>& parsed, Arm arm) {
  if (!parsed.value) return {{}, parsed.error};
  return {{Command{arm, *parsed.value}}, {}};
}

IncomingCommand fromStateCommand(const crtk_msgs::StringStamped& message) {
  const auto parsed = stateCommandFrom(message);
  if (!parsed.value) return {{}, parsed.error};
  return {{*parsed.value}, {}};
}

/// raven_automove: per arm, a translation in microns and a rotation, applied incrementally.
IncomingCommand automoveFrom(const raven_2::raven_automove& message) {
  IncomingCommand out;
  for (Arm arm : raven::kArms) {
    auto increment = poseFromTransform(message.tf_incr[raven::slot(arm)], true);
    if (!increment.value) {
      return {{}, "tf_incr[" + std::to_string(raven::index(arm)) + "]: " + increment.error};
    }
    increment.value->translation() *= kMicron;
    if (increment.value->matrix() == Eigen::Matrix4d::Identity()) continue;  // nothing to do
    out.commands.push_back(ServoCr{arm, *increment.value});
  }
  return out;
}

/// How many commands of each topic `step` names (ids of no topic left out).
std::array<std::size_t, kLockStepIdCount> namedCommands(const raven_twin::Step& step) {
  std::array<std::size_t, kLockStepIdCount> named{};
  for (std::uint8_t id : step.command_order) {
    if (id < kLockStepIdCount) ++named[id];
  }
  return named;
}

}  // namespace

/// Every topic the robot publishes.
struct Publishers {
  ::ros::Publisher operating_state, ravenstate, joint_states, step_done, refusals;
  raven::PerArm<::ros::Publisher> arm_operating_state, measured_js, setpoint_js, measured_cp,
      setpoint_cp, grasp_measured_js, grasp_measured_cf, grasp_jaw_forces;
};

/// The server's ROS side: a private callback queue spun by the serving loop (one thread, no
/// locks), and in lock-step mode the commands held back until a step names them.
class RavenRosServer::Impl final : public CommandInbox {
 public:
  Impl(RavenPlatform& platform, const std::string& ros_namespace, RosServerOptions options);
  void spinOnce(double wait);
  const RavenPlatform& platform() const { return platform_; }

  void expect(std::uint8_t id, std::string topic) override;
  void receive(std::uint8_t id, std::function<void()> apply) override;
  void refuse(std::uint8_t id, const std::string& why) override;
  void reportRefusal(std::uint8_t id, const std::string& why) override;
  ::ros::Time stamp() const override;

 private:
  using StepMessage = raven_twin::Step;
  /// A step as it arrived, and when (the command wait runs from then).
  struct PendingStep {
    StepMessage step;
    ::ros::WallTime arrived;
  };

  void subscribeCommands();
  template <typename Message, typename Parse>
  void subscribeCommand(CommandTopic topic, Parse parse);
  void apply(CommandTopic topic, const IncomingCommand& incoming);
  void runCycle();
  void publishState();
  std::string missingCommands(const StepMessage& step) const;
  std::optional<std::string> stepRefusal(const PendingStep& pending) const;
  void refuseStep(const StepMessage& step, const std::string& why);
  void runStep(const StepMessage& step);
  void answerStep(const StepMessage& step, const std::string& refused);

  RavenPlatform& platform_;
  RosServerOptions options_;
  ::ros::CallbackQueue queue_;
  ::ros::NodeHandle node_;
  std::vector<::ros::Subscriber> subscribers_;
  Publishers publishers_;
  /// Per lock-step id: the topic's name ("" while nothing serves it) and its held commands.
  std::array<std::string, kLockStepIdCount> topic_names_;
  std::array<std::deque<std::function<void()>>, kLockStepIdCount> pending_;
  std::optional<CrtkFace> crtk_;
  std::deque<PendingStep> steps_;
  std::uint64_t cycles_published_ = 0;
  ThrottledLog log_;
};

RavenRosServer::RavenRosServer(RavenPlatform& platform, const std::string& ros_namespace,
                               RosServerOptions options)
    : impl_(std::make_unique<Impl>(platform, ros_namespace, options)) {}

RavenRosServer::~RavenRosServer() = default;

void RavenRosServer::spin(double stop_after) {
  while (::ros::ok() && (stop_after <= 0.0 || impl_->platform().now() < stop_after)) {
    impl_->spinOnce(0.01);
  }
}

void RavenRosServer::spinOnce(double wait) {
  impl_->spinOnce(wait);
}

RavenRosServer::Impl::Impl(RavenPlatform& platform, const std::string& ros_namespace,
                           RosServerOptions options)
    : platform_(platform), options_(options), node_(ros_namespace) {
  node_.setCallbackQueue(&queue_);
  auto& p = publishers_;
  // Lock-step runs many cycles in a burst: queue enough that a subscriber sees every cycle.
  constexpr std::uint32_t kStateQueue = 1000;
  p.operating_state = node_.advertise<crtk_msgs::operating_state>("operating_state", kStateQueue);
  p.ravenstate = node_.advertise<raven_2::raven_state>("ravenstate", kStateQueue);
  p.joint_states = node_.advertise<sensor_msgs::JointState>("joint_states", kStateQueue);
  p.refusals = node_.advertise<std_msgs::String>(std::string(kRefusalTopic), 100);
  if (options_.lock_step) {
    p.step_done = node_.advertise<raven_twin::StepDone>(std::string(kStepDoneTopic), 100);
    subscribers_.push_back(node_.subscribe<StepMessage>(
        std::string(kStepTopic), 100,
        [this](const StepMessage::ConstPtr& step) {
          steps_.push_back({*step, ::ros::WallTime::now()});
        },
        {}, lowLatency()));
  }
  for (Arm arm : raven::kArms) {
    const auto a = raven::slot(arm);
    const std::string ns = armNamespace(arm) + "/";
    p.arm_operating_state[a] =
        node_.advertise<crtk_msgs::operating_state>(ns + "operating_state", kStateQueue);
    p.measured_js[a] = node_.advertise<sensor_msgs::JointState>(ns + "measured_js", kStateQueue);
    p.setpoint_js[a] = node_.advertise<sensor_msgs::JointState>(ns + "setpoint_js", kStateQueue);
    p.measured_cp[a] =
        node_.advertise<geometry_msgs::TransformStamped>(ns + "measured_cp", kStateQueue);
    p.setpoint_cp[a] =
        node_.advertise<geometry_msgs::TransformStamped>(ns + "setpoint_cp", kStateQueue);
    p.grasp_measured_js[a] =
        node_.advertise<sensor_msgs::JointState>(graspNamespace(arm) + "/measured_js", kStateQueue);
    if (platform_.measuredCf(arm)) {  // a platform that senses forces (the twin)
      p.grasp_measured_cf[a] = node_.advertise<geometry_msgs::WrenchStamped>(
          graspNamespace(arm) + "/measured_cf", kStateQueue);
      p.grasp_jaw_forces[a] = node_.advertise<raven_twin::GraspForces>(
          graspNamespace(arm) + "/jaw_forces", kStateQueue);
    }
  }
  subscribeCommands();
  if (options_.crtk) crtk_.emplace(platform_, node_, *options_.crtk, *this);
  publishState();
}

template <typename Message, typename Parse>
void RavenRosServer::Impl::subscribeCommand(CommandTopic topic, Parse parse) {
  constexpr std::uint32_t kCommandQueue = 10000;  // never drop a command
  expect(lockStepId(topic), std::string(topicName(topic)));
  subscribers_.push_back(node_.subscribe<Message>(
      std::string(topicName(topic)), kCommandQueue,
      [this, topic, parse](const typename Message::ConstPtr& message) {
        receive(lockStepId(topic),
                [this, topic, incoming = parse(*message)] { apply(topic, incoming); });
      },
      {}, lowLatency()));
}

void RavenRosServer::Impl::subscribeCommands() {
  using geometry_msgs::TransformStamped;
  using sensor_msgs::JointState;
  for (CommandTopic topic : {CommandTopic::StateCommand, CommandTopic::Arm1StateCommand,
                             CommandTopic::Arm2StateCommand}) {
    subscribeCommand<crtk_msgs::StringStamped>(topic, fromStateCommand);
  }
  for (Arm arm : raven::kArms) {
    subscribeCommand<JointState>(
        forArm(CommandTopic::Arm1ServoJr, arm),
        [arm](const JointState& m) { return fromParsed<ServoJr>(armJointsFromCommand(m), arm); });
    subscribeCommand<JointState>(
        forArm(CommandTopic::Arm1ServoJp, arm),
        [arm](const JointState& m) { return fromParsed<ServoJp>(armJointsFromCommand(m), arm); });
    subscribeCommand<TransformStamped>(
        forArm(CommandTopic::Arm1ServoCp, arm), [arm](const TransformStamped& m) {
          return fromParsed<ServoCp>(poseFromTransform(m.transform), arm);
        });
    subscribeCommand<TransformStamped>(
        forArm(CommandTopic::Arm1ServoCr, arm), [arm](const TransformStamped& m) {
          return fromParsed<ServoCr>(poseFromTransform(m.transform), arm);
        });
    subscribeCommand<JointState>(
        forArm(CommandTopic::Grasp1ServoJr, arm),
        [arm](const JointState& m) { return fromParsed<ServoJawJr>(graspFromCommand(m), arm); });
    subscribeCommand<JointState>(
        forArm(CommandTopic::Grasp1ServoJp, arm),
        [arm](const JointState& m) { return fromParsed<ServoJawJp>(graspFromCommand(m), arm); });
  }
  subscribeCommand<raven_2::raven_automove>(CommandTopic::RavenAutomove, automoveFrom);
}

void RavenRosServer::Impl::expect(std::uint8_t id, std::string topic) {
  topic_names_.at(id) = std::move(topic);
}

void RavenRosServer::Impl::receive(std::uint8_t id, std::function<void()> apply) {
  if (options_.lock_step) {
    pending_[id].push_back(std::move(apply));
  } else {
    apply();
  }
}

void RavenRosServer::Impl::apply(CommandTopic topic, const IncomingCommand& incoming) {
  if (!incoming.error.empty()) {
    refuse(lockStepId(topic), incoming.error);
    return;
  }
  for (const auto& command : incoming.commands) {
    const CommandResult result = platform_.send(command);
    if (!result) reportRefusal(lockStepId(topic), result.note);  // the platform logged it
  }
}

void RavenRosServer::Impl::refuse(std::uint8_t id, const std::string& why) {
  const std::string where = "refused a message on " + topic_names_[id];
  log_.warn(where, where + ": " + why, platform_.now());
  reportRefusal(id, why);
}

void RavenRosServer::Impl::reportRefusal(std::uint8_t id, const std::string& why) {
  std_msgs::String message;
  message.data = topic_names_[id] + ": " + why;
  publishers_.refusals.publish(message);
}

::ros::Time RavenRosServer::Impl::stamp() const {
  return options_.lock_step ? ::ros::Time(platform_.now()) : ::ros::Time::now();
}

void RavenRosServer::Impl::spinOnce(double wait) {
  if (!options_.lock_step) {
    queue_.callAvailable();
    runCycle();
    return;
  }
  queue_.callAvailable(::ros::WallDuration(wait));
  while (!steps_.empty()) {
    const PendingStep& front = steps_.front();
    if (const auto why = stepRefusal(front)) {
      refuseStep(front.step, *why);
    } else if (missingCommands(front.step).empty()) {
      runStep(front.step);
    } else {
      break;  // its commands may still be on their way
    }
    steps_.pop_front();
  }
}

std::string RavenRosServer::Impl::missingCommands(const StepMessage& step) const {
  const auto needed = namedCommands(step);
  std::string missing;
  for (std::size_t i = 0; i < kLockStepIdCount; ++i) {
    if (pending_[i].size() >= needed[i]) continue;
    missing += (missing.empty() ? "" : ", ") + std::to_string(needed[i] - pending_[i].size()) +
               " on " + topic_names_[i];
  }
  return missing;
}

std::optional<std::string> RavenRosServer::Impl::stepRefusal(const PendingStep& pending) const {
  const StepMessage& step = pending.step;
  if (step.cycles > kMostCyclesPerStep) {
    return "it asks for " + std::to_string(step.cycles) + " cycles, more than the " +
           std::to_string(kMostCyclesPerStep) + " one step may run";
  }
  for (std::uint8_t id : step.command_order) {
    if (id >= kLockStepIdCount || topic_names_[id].empty()) {
      return "it names command topic id " + std::to_string(id) + ", which this node does not serve";
    }
  }
  const double waited = (::ros::WallTime::now() - pending.arrived).toSec();
  if (waited < options_.command_wait) return std::nullopt;
  const std::string missing = missingCommands(step);
  if (missing.empty()) return std::nullopt;
  return "the commands it names did not all arrive within " +
         std::to_string(options_.command_wait) + " s (missing " + missing + ")";
}

void RavenRosServer::Impl::refuseStep(const StepMessage& step, const std::string& why) {
  // The commands of it that did arrive go too: a later step must not take them for its own.
  const auto named = namedCommands(step);
  for (std::size_t i = 0; i < kLockStepIdCount; ++i) {
    const auto dropped = static_cast<long>(std::min(named[i], pending_[i].size()));
    pending_[i].erase(pending_[i].begin(), pending_[i].begin() + dropped);
  }
  log_.warn("refused a lock-step step",
            "refused lock-step step " + std::to_string(step.seq) + ": " + why, platform_.now());
  std_msgs::String message;
  message.data = std::string(kStepTopic) + ": step " + std::to_string(step.seq) + ": " + why;
  publishers_.refusals.publish(message);
  answerStep(step, why);
}

void RavenRosServer::Impl::runStep(const StepMessage& step) {
  for (std::uint8_t id : step.command_order) {
    auto& queue = pending_[id];
    const auto apply = std::move(queue.front());
    queue.pop_front();
    apply();
  }
  try {
    for (std::uint32_t c = 0; c < step.cycles && ::ros::ok(); ++c) runCycle();
  } catch (const std::exception& e) {  // the platform failed (a twin's world blew up): say so
    answerStep(step, std::string("the platform failed: ") + e.what());
    throw;
  }
  if (step.cycles == 0) publishState();
  answerStep(step, {});
}

void RavenRosServer::Impl::answerStep(const StepMessage& step, const std::string& refused) {
  raven_twin::StepDone done;
  done.header.stamp = stamp();
  done.seq = step.seq;
  done.refused = refused;
  publishers_.step_done.publish(done);
}

void RavenRosServer::Impl::runCycle() {
  platform_.advance(raven::kControlCycle);
  if (options_.after_cycle) options_.after_cycle();
  publishState();
}

void RavenRosServer::Impl::publishState() {
  auto& p = publishers_;
  const ::ros::Time now = stamp();
  const auto status = toOperatingState(platform_.operatingStatus(), now);
  p.operating_state.publish(status);
  sensor_msgs::JointState both;
  both.header.stamp = now;
  for (Arm arm : raven::kArms) {
    const auto a = raven::slot(arm);
    const std::string_view colour = armColour(arm);
    p.arm_operating_state[a].publish(status);
    const Arm source = measuredJsSource(arm, options_.arm_swap);
    p.measured_js[a].publish(toJointState(platform_.measuredJs(source), armColour(source), now));
    p.setpoint_js[a].publish(toJointState(platform_.setpointJs(arm), colour, now));
    const std::string base = std::string(colour) + "_base";
    const std::string tool = std::string(colour) + "_tool";
    p.measured_cp[a].publish(toTransformStamped(platform_.measuredCp(arm).pose, now, base, tool));
    p.setpoint_cp[a].publish(toTransformStamped(platform_.setpointCp(arm).pose, now, base, tool));
    const JointSample measured = platform_.measuredJs(arm);
    p.grasp_measured_js[a].publish(toGraspState(measured, colour, now));
    if (p.grasp_measured_cf[a]) {
      if (const auto forces = platform_.measuredCf(arm)) {
        p.grasp_measured_cf[a].publish(toWrenchStamped(*forces, now, "world"));
        p.grasp_jaw_forces[a].publish(toGraspForces(*forces, now, "world"));
      }
    }
    if (cycles_published_ % kJointStatesEvery == 0) {
      const auto arm_state = toJointState(measured, colour, now);
      both.name.insert(both.name.end(), arm_state.name.begin(), arm_state.name.end());
      both.position.insert(both.position.end(), arm_state.position.begin(),
                           arm_state.position.end());
      both.velocity.insert(both.velocity.end(), arm_state.velocity.begin(),
                           arm_state.velocity.end());
      both.effort.insert(both.effort.end(), arm_state.effort.begin(), arm_state.effort.end());
    }
  }
  if (cycles_published_ % kJointStatesEvery == 0) p.joint_states.publish(both);
  if (const auto state = platform_.ravenState()) p.ravenstate.publish(toRavenState(*state, now));
  if (crtk_) crtk_->publishState(now);
  ++cycles_published_;
}

}  // namespace bridge::ros1
