#pragma once
// Where the ROS server's command topics deliver: one queue for every dialect, so commands of the
// robot's own topics and of the standard CRTK face take their places in one lock-step order.

#include <ros/time.h>

#include <cstdint>
#include <functional>
#include <string>

namespace bridge::ros1 {

/// The server's side of its command topics, as a part of it (the CRTK face) sees it.
class CommandInbox {
 public:
  virtual ~CommandInbox() = default;

  /// Registers the topic a lock-step id stands for (refusals and missing commands name it).
  virtual void expect(std::uint8_t id, std::string topic) = 0;
  /// A message arrived on topic `id`: `apply` runs now (wall clock) or when a lock-step step
  /// names it, in the step's order.
  virtual void receive(std::uint8_t id, std::function<void()> apply) = 0;
  /// A message of topic `id` that could not be read: logs and publishes why.
  virtual void refuse(std::uint8_t id, const std::string& why) = 0;
  /// A command of topic `id` refused by what took it (which logged it): publishes why.
  virtual void reportRefusal(std::uint8_t id, const std::string& why) = 0;
  /// The stamp of what is published now (simulated time in lock-step).
  virtual ::ros::Time stamp() const = 0;
};

}  // namespace bridge::ros1
