#include "bridge/ros/raven_ros_client.hpp"

#include <crtk_msgs/StringStamped.h>
#include <geometry_msgs/WrenchStamped.h>
#include <raven_twin/GraspForces.h>
#include <raven_twin/Step.h>
#include <raven_twin/StepDone.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <vector>

#include "bridge/command_checks.hpp"
#include "bridge/joint_trajectory.hpp"
#include "bridge/overloaded.hpp"
#include "bridge/ros/command_topics.hpp"
#include "bridge/ros/low_latency.hpp"
#include "bridge/ros/ros_conversions.hpp"
#include "bridge/throttled_log.hpp"
#include "bridge/wall_pacer.hpp"
#include "common/printable.hpp"
#include "raven/platform_profile.hpp"

namespace bridge::ros1 {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

/// The paper's controller sends 15 values (7 used, 8 zeros): the form the robot is known to take.
sensor_msgs::JointState jointCommand(const ArmJoints& q) {
  sensor_msgs::JointState m;
  m.header.stamp = ::ros::Time::now();
  m.position.assign(15, 0.0);
  std::copy(q.data(), q.data() + raven::kJointCount, m.position.begin());
  return m;
}

sensor_msgs::JointState graspCommand(double value) {
  sensor_msgs::JointState m;
  m.header.stamp = ::ros::Time::now();
  m.position = {value};
  return m;
}

geometry_msgs::TransformStamped poseCommand(const Eigen::Isometry3d& pose) {
  return toTransformStamped(pose, ::ros::Time::now(), "", "");
}

// Where each state topic's latest stamp lives in state_stamps_.
constexpr std::size_t kMeasuredStamp = 0, kSetpointStamp = 2, kStatusStamp = 4, kRavenStamp = 5;

}  // namespace

/// The ROS side: node handle on a private callback queue, publishers and subscribers.
struct Connection {
  ::ros::CallbackQueue queue;
  ::ros::NodeHandle node;
  std::array<::ros::Publisher, kCommandTopicCount> commands;
  ::ros::Publisher step;
  std::vector<::ros::Subscriber> subscribers;
  /// Topics only some robots publish (the twin's grasp forces): not waited for.
  std::vector<::ros::Subscriber> optional_subscribers;
  bool warned_names = false;
};

/// The client's state: the robot's latest messages (taken in only while the client spins its
/// private queue, in advance()), moves being streamed, and the lock-step bookkeeping.
class RavenRosClient::Impl {
 public:
  explicit Impl(RosClientOptions options);
  CommandResult send(const PlatformCommand& command);
  OperatingStatus operatingStatus() const;
  JointSample measuredJs(Arm arm) const { return measured_[slot(arm)].value_or(JointSample{}); }
  JointSample setpointJs(Arm arm) const { return setpoint_[slot(arm)].value_or(JointSample{}); }
  PoseSample measuredCp(Arm arm) const { return measured_cp_[slot(arm)].value_or(PoseSample{}); }
  PoseSample setpointCp(Arm arm) const { return setpoint_cp_[slot(arm)].value_or(PoseSample{}); }
  const std::optional<RavenStateSnapshot>& ravenState() const { return raven_state_; }
  std::optional<GrasperForces> measuredCf(Arm arm) const;
  bool lockStep() const { return options_.lock_step; }
  double now() const;
  void advance(double seconds);
  const std::string& lostReason() const { return lost_reason_; }

 private:
  /// A move_jp the client streams as servo_jp, one sample per robot cycle.
  struct LocalMove {
    JointTrajectory trajectory;
    double start;
  };

  void subscribe();
  void advertiseCommands();
  void subscribeStatus();
  /// The arm's joint and pose topics (measured and setpoint).
  void subscribeArm(Arm topic_arm);
  /// The twin's grasp force topics (optional: the physical robot has none).
  void subscribeForces(Arm arm);
  /// A message's time: its stamp in lock-step (the simulated clock), else when it arrived.
  double stampOf(const ::ros::Time& stamp) { return options_.lock_step ? stamp.toSec() : now(); }
  void waitForRobot();
  CommandResult publish(CommandTopic topic, const PlatformCommand& command);
  void streamMoves(double at);
  void stepLockStep(std::uint32_t cycles);
  void waitWall(double until);
  void lose(std::string why);
  /// A robot's message that could not be read: logged once a second per topic.
  void ignored(const std::string& what, const std::string& why);
  bool statesAt(::ros::Time stamp) const;

  RosClientOptions options_;
  raven::JointLimits joint_limits_;
  Connection connection_;
  std::optional<OperatingStatus> status_;
  raven::PerArm<std::optional<JointSample>> measured_, setpoint_;
  raven::PerArm<std::optional<PoseSample>> measured_cp_, setpoint_cp_;
  std::optional<RavenStateSnapshot> raven_state_;
  /// Per grasper: the latest jaw_forces and measured_cf (the twin's; a physical robot has none),
  /// and the forces read from the two once they carry the same cycle's stamp.
  std::array<std::optional<raven_twin::GraspForces>, 2> jaw_forces_;
  raven::PerArm<std::optional<geometry_msgs::WrenchStamped>> wrench_;
  raven::PerArm<std::optional<GrasperForces>> cf_;
  void readForces(Arm arm, double time);
  raven::PerArm<std::optional<LocalMove>> moves_;
  std::vector<std::uint8_t> command_order_;  ///< lock-step: topics sent on since the last step
  std::uint64_t step_seq_ = 0;
  std::optional<raven_twin::StepDone> step_done_;  ///< lock-step: the node's latest answer
  /// The latest stamp of measured_js x2, setpoint_js x2, operating_state, ravenstate (unset
  /// until the first message).
  std::array<std::optional<::ros::Time>, 6> state_stamps_;
  double sim_time_ = 0.0;   ///< lock-step: the node's clock at the last answer
  double requested_ = 0.0;  ///< platform time this client has asked for
  long long cycles_stepped_ = 0;
  Clock::time_point start_;
  Clock::time_point last_measured_;
  WallPacer pacer_;
  std::string lost_reason_;
  ThrottledLog log_;
};

RavenRosClient::RavenRosClient(RosClientOptions options)
    : impl_(std::make_unique<Impl>(std::move(options))) {}
RavenRosClient::~RavenRosClient() = default;
CommandResult RavenRosClient::send(const PlatformCommand& command) {
  return impl_->send(command);
}
OperatingStatus RavenRosClient::operatingStatus() const {
  return impl_->operatingStatus();
}
JointSample RavenRosClient::measuredJs(Arm arm) const {
  return impl_->measuredJs(arm);
}
JointSample RavenRosClient::setpointJs(Arm arm) const {
  return impl_->setpointJs(arm);
}
PoseSample RavenRosClient::measuredCp(Arm arm) const {
  return impl_->measuredCp(arm);
}
PoseSample RavenRosClient::setpointCp(Arm arm) const {
  return impl_->setpointCp(arm);
}
std::optional<GrasperForces> RavenRosClient::Impl::measuredCf(Arm arm) const {
  return cf_[slot(arm)];
}

void RavenRosClient::Impl::readForces(Arm arm, double time) {
  const auto& jaws = jaw_forces_[slot(arm)];
  const auto& wrench = wrench_[slot(arm)];
  // Both halves of the same cycle (the twin stamps them alike), or wait for the other.
  if (!jaws || !wrench || jaws->header.stamp != wrench->header.stamp) return;
  auto parsed = grasperForcesFrom(*jaws, wrench->wrench);
  if (!parsed.value) {
    ignored(graspNamespace(arm) + " forces", parsed.error);
    return;
  }
  parsed.value->time = time;
  cf_[slot(arm)] = parsed.value;
}

std::optional<GrasperForces> RavenRosClient::measuredCf(Arm arm) const {
  return impl_->measuredCf(arm);
}

std::optional<RavenStateSnapshot> RavenRosClient::ravenState() const {
  return impl_->ravenState();
}
ClockKind RavenRosClient::clockKind() const {
  return impl_->lockStep() ? ClockKind::Simulated : ClockKind::Wall;
}
double RavenRosClient::now() const {
  return impl_->now();
}
void RavenRosClient::advance(double seconds) {
  impl_->advance(seconds);
}
const std::string& RavenRosClient::lostReason() const {
  return impl_->lostReason();
}

RavenRosClient::Impl::Impl(RosClientOptions options)
    : options_(std::move(options)),
      joint_limits_(raven::builtinProfile(options_.profile).limits),
      start_(Clock::now()),
      last_measured_(start_) {
  subscribe();
  waitForRobot();
}

void RavenRosClient::Impl::subscribe() {
  auto& c = connection_;
  c.node = ::ros::NodeHandle(options_.robot_namespace);
  c.node.setCallbackQueue(&c.queue);
  advertiseCommands();
  subscribeStatus();
  for (Arm arm : raven::kArms) subscribeArm(arm);
  for (Arm arm : raven::kArms) subscribeForces(arm);
  if (options_.lock_step) {
    c.step = c.node.advertise<raven_twin::Step>(std::string(kStepTopic), 100);
    c.subscribers.push_back(c.node.subscribe<raven_twin::StepDone>(
        std::string(kStepDoneTopic), 100,
        [this](const raven_twin::StepDone::ConstPtr& m) { step_done_ = *m; }, {}, lowLatency()));
  }
}

void RavenRosClient::Impl::advertiseCommands() {
  auto& c = connection_;
  for (CommandTopic topic : allCommandTopics()) {
    const std::string name(topicName(topic));
    auto& publisher = c.commands[static_cast<std::size_t>(topic)];
    constexpr std::uint32_t kQueue = 10000;
    switch (messageType(topic)) {
      case CommandMessage::StringStamped:
        publisher = c.node.advertise<crtk_msgs::StringStamped>(name, kQueue);
        break;
      case CommandMessage::JointState:
        publisher = c.node.advertise<sensor_msgs::JointState>(name, kQueue);
        break;
      case CommandMessage::TransformStamped:
        publisher = c.node.advertise<geometry_msgs::TransformStamped>(name, kQueue);
        break;
      case CommandMessage::RavenAutomove:
        break;  // the client expresses increments as servo_cr
    }
  }
}

void RavenRosClient::Impl::subscribeStatus() {
  auto& c = connection_;
  c.subscribers.push_back(c.node.subscribe<crtk_msgs::operating_state>(
      "operating_state", 10,
      [this](const crtk_msgs::operating_state::ConstPtr& m) {
        const auto parsed = operatingStatusFrom(*m);
        if (!parsed.value) {
          ignored("operating_state", parsed.error);
          return;
        }
        status_ = parsed.value;
        state_stamps_[kStatusStamp] = m->header.stamp;
      },
      {}, lowLatency()));
  c.subscribers.push_back(c.node.subscribe<raven_2::raven_state>(
      "ravenstate", 10,
      [this](const raven_2::raven_state::ConstPtr& m) {
        raven_state_ = ravenStateFrom(*m);
        state_stamps_[kRavenStamp] = m->hdr.stamp;
      },
      {}, lowLatency()));
}

void RavenRosClient::Impl::subscribeArm(Arm topic_arm) {
  auto& c = connection_;
  const std::string ns = armNamespace(topic_arm) + "/";
  const Arm source = measuredJsSource(topic_arm, options_.arm_swap);
  c.subscribers.push_back(c.node.subscribe<sensor_msgs::JointState>(
      ns + "measured_js", 10,
      [this, topic_arm, source](const sensor_msgs::JointState::ConstPtr& m) {
        auto parsed = jointSampleFromState(*m);
        if (!parsed.value) {
          ignored(armNamespace(topic_arm) + "/measured_js", parsed.error);
          return;
        }
        const std::string colour(armColour(source));
        if (!m->name.empty() && m->name[0].rfind(colour, 0) != 0 && !connection_.warned_names) {
          connection_.warned_names = true;
          spdlog::warn(
              "{}/measured_js carries '{}' while the arm swap is {}: check the client's "
              "arm_swap setting against the robot",
              armNamespace(topic_arm), common::printable(m->name[0], 40),
              options_.arm_swap ? "on" : "off");
        }
        parsed.value->time = stampOf(m->header.stamp);
        measured_[slot(source)] = parsed.value;
        state_stamps_[kMeasuredStamp + slot(topic_arm)] = m->header.stamp;
        last_measured_ = Clock::now();
      },
      {}, lowLatency()));
  c.subscribers.push_back(c.node.subscribe<sensor_msgs::JointState>(
      ns + "setpoint_js", 10,
      [this, topic_arm](const sensor_msgs::JointState::ConstPtr& m) {
        auto parsed = jointSampleFromState(*m);
        if (!parsed.value) {
          ignored(armNamespace(topic_arm) + "/setpoint_js", parsed.error);
          return;
        }
        parsed.value->time = stampOf(m->header.stamp);
        setpoint_[slot(topic_arm)] = parsed.value;
        state_stamps_[kSetpointStamp + slot(topic_arm)] = m->header.stamp;
      },
      {}, lowLatency()));
  for (const auto& [name, poses] :
       {std::pair{"measured_cp", &measured_cp_}, {"setpoint_cp", &setpoint_cp_}}) {
    auto* target = poses;  // a lambda may not capture a structured binding before C++20
    c.subscribers.push_back(c.node.subscribe<geometry_msgs::TransformStamped>(
        ns + name, 10,
        [this, topic_arm, target](const geometry_msgs::TransformStamped::ConstPtr& m) {
          const auto pose = poseFromTransform(m->transform);
          if (pose.value)
            (*target)[slot(topic_arm)] = PoseSample{stampOf(m->header.stamp), *pose.value};
        },
        {}, lowLatency()));
  }
}

void RavenRosClient::Impl::subscribeForces(Arm arm) {
  auto& c = connection_;
  const std::string ns = graspNamespace(arm) + "/";
  c.optional_subscribers.push_back(c.node.subscribe<raven_twin::GraspForces>(
      ns + "jaw_forces", 10,
      [this, arm](const raven_twin::GraspForces::ConstPtr& m) {
        jaw_forces_[slot(arm)] = *m;
        readForces(arm, stampOf(m->header.stamp));
      },
      {}, lowLatency()));
  c.optional_subscribers.push_back(c.node.subscribe<geometry_msgs::WrenchStamped>(
      ns + "measured_cf", 10,
      [this, arm](const geometry_msgs::WrenchStamped::ConstPtr& m) {
        wrench_[slot(arm)] = *m;
        readForces(arm, stampOf(m->header.stamp));
      },
      {}, lowLatency()));
}

void RavenRosClient::Impl::waitForRobot() {
  auto& c = connection_;
  const auto deadline = start_ + std::chrono::duration_cast<Clock::duration>(
                                     std::chrono::duration<double>(options_.connect_timeout));
  // Commands published before the robot's subscription is up would be lost: wait for it.
  auto missing = [&]() -> std::string {
    const std::vector<CommandTopic> essential{CommandTopic::StateCommand, CommandTopic::Arm1ServoJr,
                                              CommandTopic::Arm2ServoJr, CommandTopic::Arm1ServoJp,
                                              CommandTopic::Arm2ServoJp};
    for (CommandTopic topic :
         options_.lock_step
             ? std::vector<CommandTopic>(allCommandTopics().begin(), allCommandTopics().end())
             : essential) {
      const auto& publisher = c.commands[static_cast<std::size_t>(topic)];
      if (publisher && publisher.getNumSubscribers() == 0) {
        return "nobody subscribes to " + std::string(topicName(topic));
      }
    }
    for (const auto& subscriber : c.subscribers) {
      if (subscriber.getNumPublishers() == 0) return "nobody publishes " + subscriber.getTopic();
    }
    if (options_.lock_step && c.step.getNumSubscribers() == 0) {
      return "nobody subscribes to " + std::string(kStepTopic) + " (is the node in --lock-step?)";
    }
    return {};
  };
  std::string why = missing();
  while (!why.empty() && Clock::now() < deadline) {
    c.queue.callAvailable(::ros::WallDuration(0.01));
    why = missing();
  }
  if (!why.empty()) {
    throw std::runtime_error("no Raven-II found under namespace '" + c.node.getNamespace() +
                             "' after " + std::to_string(options_.connect_timeout) + " s: " + why +
                             " (is ROS_MASTER_URI right, is the robot running?)");
  }
  if (options_.lock_step) {
    stepLockStep(0);
  } else {
    while ((!measured_[0] || !measured_[1] || !setpoint_[0] || !setpoint_[1] || !status_) &&
           Clock::now() < deadline) {
      c.queue.callAvailable(::ros::WallDuration(0.01));
    }
    last_measured_ = Clock::now();
  }
  if (!measured_[0] || !measured_[1] || !status_) {
    throw std::runtime_error(
        "the Raven-II's topics are up but it sent no measured_js and "
        "operating_state within the connect timeout");
  }
}

CommandResult RavenRosClient::Impl::send(const PlatformCommand& command) {
  if (!lost_reason_.empty()) return CommandResult::refused("robot lost: " + lost_reason_);
  return std::visit(
      Overloaded{
          [&](StateCommand) { return publish(CommandTopic::StateCommand, command); },
          [&](const ServoJp& c) {
            if (auto why = nonFiniteJoint(c.position)) return CommandResult::refused(*why);
            if (auto why = jumpRefusal(c.position, setpointJs(c.arm).position, options_.limits)) {
              return CommandResult::refused(*why);
            }
            moves_[slot(c.arm)].reset();
            return publish(forArm(CommandTopic::Arm1ServoJp, c.arm), command);
          },
          [&](const ServoJr& c) {
            if (auto why = nonFiniteJoint(c.increment)) return CommandResult::refused(*why);
            if (auto why = jumpRefusal(c.increment, ArmJoints::Zero(), options_.limits)) {
              return CommandResult::refused(*why);
            }
            moves_[slot(c.arm)].reset();
            return publish(forArm(CommandTopic::Arm1ServoJr, c.arm), command);
          },
          [&](const MoveJp& c) {
            if (auto why = nonFiniteJoint(c.goal)) return CommandResult::refused(*why);
            if (!operatingStatus().ready()) {
              return CommandResult::refused("the robot is not enabled and homed");
            }
            const ArmJoints goal = c.goal.cwiseMax(joint_limits_.low).cwiseMin(joint_limits_.high);
            moves_[slot(c.arm)] = LocalMove{
                JointTrajectory(setpointJs(c.arm).position, goal, options_.limits.moveVelocity(),
                                options_.limits.move_acceleration),
                now()};
            return CommandResult::ok(goal == c.goal ? "" : "clamped to the joint limits");
          },
          [&](const ServoCp& c) {
            if (!c.pose.matrix().allFinite())
              return CommandResult::refused("NaN or inf in the pose");
            moves_[slot(c.arm)].reset();
            return publish(forArm(CommandTopic::Arm1ServoCp, c.arm), command);
          },
          [&](const ServoCr& c) {
            if (!c.increment.matrix().allFinite()) {
              return CommandResult::refused("NaN or inf in the increment");
            }
            moves_[slot(c.arm)].reset();
            return publish(forArm(CommandTopic::Arm1ServoCr, c.arm), command);
          },
          [&](const ServoJawJp& c) {
            if (!std::isfinite(c.opening)) return CommandResult::refused("NaN or inf opening");
            return publish(forArm(CommandTopic::Grasp1ServoJp, c.arm), command);
          },
          [&](const ServoJawJr& c) {
            if (!std::isfinite(c.increment)) return CommandResult::refused("NaN or inf increment");
            return publish(forArm(CommandTopic::Grasp1ServoJr, c.arm), command);
          },
      },
      command);
}

CommandResult RavenRosClient::Impl::publish(CommandTopic topic, const PlatformCommand& command) {
  auto& publisher = connection_.commands[static_cast<std::size_t>(topic)];
  std::visit(Overloaded{
                 [&](StateCommand c) {
                   crtk_msgs::StringStamped m;
                   m.header.stamp = ::ros::Time::now();
                   m.string = std::string(wireName(c));
                   publisher.publish(m);
                 },
                 [&](const ServoJp& c) { publisher.publish(jointCommand(c.position)); },
                 [&](const ServoJr& c) { publisher.publish(jointCommand(c.increment)); },
                 [&](const MoveJp&) {},
                 [&](const ServoCp& c) { publisher.publish(poseCommand(c.pose)); },
                 [&](const ServoCr& c) { publisher.publish(poseCommand(c.increment)); },
                 [&](const ServoJawJp& c) { publisher.publish(graspCommand(c.opening)); },
                 [&](const ServoJawJr& c) { publisher.publish(graspCommand(c.increment)); },
             },
             command);
  if (options_.lock_step) command_order_.push_back(static_cast<std::uint8_t>(topic));
  return CommandResult::ok("sent on " + std::string(topicName(topic)));
}

OperatingStatus RavenRosClient::Impl::operatingStatus() const {
  if (!lost_reason_.empty()) return {OperatingState::Fault, false, false};
  OperatingStatus s = status_.value_or(OperatingStatus{});
  for (const auto& move : moves_) s.is_busy = s.is_busy || move.has_value();
  return s;
}

double RavenRosClient::Impl::now() const {
  return options_.lock_step ? sim_time_ : secondsSince(start_);
}

void RavenRosClient::Impl::advance(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0.0) {
    throw std::invalid_argument("advance: seconds must be finite and >= 0, not " +
                                std::to_string(seconds));
  }
  requested_ += seconds;
  if (!options_.lock_step) {
    if (lost_reason_.empty()) streamMoves(now());
    waitWall(requested_);
    return;
  }
  // Cycles this client asked for, against cycles it has had stepped (others may step the node
  // too; the node's clock is sim_time_).
  const auto target = std::llround(requested_ / options_.limits.cycle);
  while (cycles_stepped_ < target && lost_reason_.empty()) {
    if (moves_[0] || moves_[1]) {  // one servo_jp sample per robot cycle
      streamMoves(sim_time_ + options_.limits.cycle);
      stepLockStep(1);
    } else {
      stepLockStep(static_cast<std::uint32_t>(
          std::min<long long>(target - cycles_stepped_, kMostCyclesPerStep)));
    }
  }
}

void RavenRosClient::Impl::streamMoves(double at) {
  for (Arm arm : raven::kArms) {
    auto& move = moves_[slot(arm)];
    if (!move) continue;
    const double t = at - move->start;
    publish(forArm(CommandTopic::Arm1ServoJp, arm), ServoJp{arm, move->trajectory.at(t)});
    if (t >= move->trajectory.duration()) move.reset();
  }
}

bool RavenRosClient::Impl::statesAt(::ros::Time stamp) const {
  for (const auto& s : state_stamps_) {
    if (!s || *s < stamp) return false;
  }
  return true;
}

void RavenRosClient::Impl::stepLockStep(std::uint32_t cycles) {
  auto& c = connection_;
  raven_twin::Step step;
  step.seq = ++step_seq_;
  step.cycles = cycles;
  step.command_order = std::move(command_order_);
  command_order_.clear();
  c.step.publish(step);
  cycles_stepped_ += cycles;
  // The node needs some wall time per cycle; give it at least real time on top of the timeout.
  const double allowed = options_.robot_timeout + cycles * options_.limits.cycle;
  const auto started = Clock::now();
  auto answered = [&] {
    return step_done_ && step_done_->seq == step.seq &&
           (!step_done_->refused.empty() || statesAt(step_done_->header.stamp));
  };
  while (!answered()) {
    if (secondsSince(started) > allowed) {
      lose("no answer to lock-step step " + std::to_string(step.seq) + " within " +
           std::to_string(allowed) + " s (the twin node is gone or stuck)");
      return;
    }
    c.queue.callAvailable(::ros::WallDuration(0.005));
  }
  if (!step_done_->refused.empty()) {
    lose("the twin node refused lock-step step " + std::to_string(step.seq) + ": " +
         step_done_->refused);
    return;
  }
  sim_time_ = step_done_->header.stamp.toSec();
}

void RavenRosClient::Impl::waitWall(double until) {
  auto& c = connection_;
  for (double left = pacer_.secondsUntil(until); left > 0.0; left = pacer_.secondsUntil(until)) {
    c.queue.callAvailable(::ros::WallDuration(left));
  }
  c.queue.callAvailable();
  if (lost_reason_.empty() && secondsSince(last_measured_) > options_.robot_timeout) {
    lose("no measured_js from the robot for " + std::to_string(secondsSince(last_measured_)) +
         " s");
  }
}

void RavenRosClient::Impl::ignored(const std::string& what, const std::string& why) {
  log_.warn(what + " ignored", what + " ignored: " + why, secondsSince(start_));
}

void RavenRosClient::Impl::lose(std::string why) {
  spdlog::error("Raven-II lost: {}", why);
  lost_reason_ = std::move(why);
  for (auto& move : moves_) move.reset();
}

}  // namespace bridge::ros1
