#pragma once
// The Raven-II's ROS topic names: the command topics it subscribes to (with the ids the twin
// node's lock-step protocol orders them by), the per-arm namespaces, and the command topics of
// the twin node's standard CRTK face.

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

#include "raven/arm.hpp"

namespace bridge::ros1 {

/// Every command topic of the robot's CRTK interface that this project uses. Each arm-2 topic
/// directly follows its arm-1 twin.
enum class CommandTopic : std::uint8_t {
  StateCommand,
  Arm1StateCommand,
  Arm2StateCommand,
  Arm1ServoJr,
  Arm2ServoJr,
  Arm1ServoJp,
  Arm2ServoJp,
  Arm1ServoCp,
  Arm2ServoCp,
  Arm1ServoCr,
  Arm2ServoCr,
  Grasp1ServoJr,
  Grasp2ServoJr,
  Grasp1ServoJp,
  Grasp2ServoJp,
  RavenAutomove,
};
inline constexpr std::size_t kCommandTopicCount = 16;

/// The message type a command topic carries.
enum class CommandMessage { StringStamped, JointState, TransformStamped, RavenAutomove };

/// "state_command", "arm1/servo_jr", "grasp2/servo_jp", "raven_automove", ...: relative names,
/// resolved in the robot's namespace.
std::string_view topicName(CommandTopic topic);
CommandMessage messageType(CommandTopic topic);
const std::array<CommandTopic, kCommandTopicCount>& allCommandTopics();

/// `arm`'s version of a per-arm topic given by its arm-1 name: forArm(Arm1ServoJr, Right) is
/// Arm2ServoJr.
CommandTopic forArm(CommandTopic arm1_topic, raven::Arm arm);

/// The command topics of one arm in the twin node's standard CRTK face (under its own namespace,
/// one per arm, the jaw under the arm's `jaw/`), in lock-step id order.
enum class CrtkCommand : std::uint8_t {
  StateCommand,
  ServoJp,
  ServoJr,
  ServoCp,
  ServoCr,
  MoveJp,
  MoveCp,
  JawServoJp,
  JawServoJr,
  JawMoveJp,
};
inline constexpr std::size_t kCrtkCommandCount = 10;
/// "servo_jp", "jaw/move_jp", ...: relative to the arm's CRTK namespace.
std::string_view relativeName(CrtkCommand command);

/// Lock-step ids: the robot's command topics (0-15, their CommandTopic value), then the CRTK
/// face's commands of arm 1 (16-25, in CrtkCommand order), then arm 2's (26-35).
inline constexpr std::size_t kLockStepIdCount = kCommandTopicCount + 2 * kCrtkCommandCount;
std::uint8_t lockStepId(CommandTopic topic);
std::uint8_t lockStepId(CrtkCommand command, raven::Arm arm);

/// "arm1" (gold, left) or "arm2" (green, right), and "grasp1" / "grasp2".
std::string armNamespace(raven::Arm arm);
std::string graspNamespace(raven::Arm arm);
/// "gold" or "green": the robot's names for its arms (joint names gold_shoulder, ...).
std::string_view armColour(raven::Arm arm);

/// The arm whose joints the robot publishes on `arm`'s measured_js: upstream publishes the green
/// arm's on arm1 and the gold arm's on arm2 (the swap); without the swap, the arm itself.
raven::Arm measuredJsSource(raven::Arm topic_arm, bool arm_swap);

/// Lock-step protocol topics (this project's twin node only).
inline constexpr std::string_view kStepTopic = "raven_twin/step";
inline constexpr std::string_view kStepDoneTopic = "raven_twin/step_done";
/// The most 1 ms cycles one step may ask for (a minute of robot time): the node refuses more,
/// so no single request holds it for long; a client splits longer advances into several steps.
inline constexpr std::uint32_t kMostCyclesPerStep = 60'000;
/// Where the twin node says why it refused a command (std_msgs/String).
inline constexpr std::string_view kRefusalTopic = "raven_twin/refusals";

}  // namespace bridge::ros1
