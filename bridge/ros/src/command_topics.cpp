#include "bridge/ros/command_topics.hpp"

namespace bridge::ros1 {

namespace {

struct TopicEntry {
  CommandTopic topic;
  std::string_view name;
  CommandMessage message;
};

using M = CommandMessage;
constexpr std::array<TopicEntry, kCommandTopicCount> kTopics{{
    {CommandTopic::StateCommand, "state_command", M::StringStamped},
    {CommandTopic::Arm1StateCommand, "arm1/state_command", M::StringStamped},
    {CommandTopic::Arm2StateCommand, "arm2/state_command", M::StringStamped},
    {CommandTopic::Arm1ServoJr, "arm1/servo_jr", M::JointState},
    {CommandTopic::Arm2ServoJr, "arm2/servo_jr", M::JointState},
    {CommandTopic::Arm1ServoJp, "arm1/servo_jp", M::JointState},
    {CommandTopic::Arm2ServoJp, "arm2/servo_jp", M::JointState},
    {CommandTopic::Arm1ServoCp, "arm1/servo_cp", M::TransformStamped},
    {CommandTopic::Arm2ServoCp, "arm2/servo_cp", M::TransformStamped},
    {CommandTopic::Arm1ServoCr, "arm1/servo_cr", M::TransformStamped},
    {CommandTopic::Arm2ServoCr, "arm2/servo_cr", M::TransformStamped},
    {CommandTopic::Grasp1ServoJr, "grasp1/servo_jr", M::JointState},
    {CommandTopic::Grasp2ServoJr, "grasp2/servo_jr", M::JointState},
    {CommandTopic::Grasp1ServoJp, "grasp1/servo_jp", M::JointState},
    {CommandTopic::Grasp2ServoJp, "grasp2/servo_jp", M::JointState},
    {CommandTopic::RavenAutomove, "raven_automove", M::RavenAutomove},
}};

constexpr std::array<std::string_view, kCrtkCommandCount> kCrtkNames{
    "state_command", "servo_jp", "servo_jr",     "servo_cp",     "servo_cr",
    "move_jp",       "move_cp",  "jaw/servo_jp", "jaw/servo_jr", "jaw/move_jp"};

}  // namespace

std::string_view relativeName(CrtkCommand command) {
  return kCrtkNames[static_cast<std::size_t>(command)];
}

std::uint8_t lockStepId(CommandTopic topic) {
  return static_cast<std::uint8_t>(topic);
}

std::uint8_t lockStepId(CrtkCommand command, raven::Arm arm) {
  return static_cast<std::uint8_t>(kCommandTopicCount + raven::slot(arm) * kCrtkCommandCount +
                                   static_cast<std::size_t>(command));
}

std::string_view topicName(CommandTopic topic) {
  return kTopics[static_cast<std::size_t>(topic)].name;
}

CommandMessage messageType(CommandTopic topic) {
  return kTopics[static_cast<std::size_t>(topic)].message;
}

const std::array<CommandTopic, kCommandTopicCount>& allCommandTopics() {
  static const auto all = [] {
    std::array<CommandTopic, kCommandTopicCount> out{};
    for (std::size_t i = 0; i < kCommandTopicCount; ++i) out[i] = kTopics[i].topic;
    return out;
  }();
  return all;
}

CommandTopic forArm(CommandTopic arm1_topic, raven::Arm arm) {
  return static_cast<CommandTopic>(static_cast<std::uint8_t>(arm1_topic) + raven::index(arm));
}

std::string armNamespace(raven::Arm arm) {
  return arm == raven::Arm::Left ? "arm1" : "arm2";
}
std::string graspNamespace(raven::Arm arm) {
  return arm == raven::Arm::Left ? "grasp1" : "grasp2";
}
std::string_view armColour(raven::Arm arm) {
  return arm == raven::Arm::Left ? "gold" : "green";
}

raven::Arm measuredJsSource(raven::Arm topic_arm, bool arm_swap) {
  if (!arm_swap) return topic_arm;
  return topic_arm == raven::Arm::Left ? raven::Arm::Right : raven::Arm::Left;
}

}  // namespace bridge::ros1
