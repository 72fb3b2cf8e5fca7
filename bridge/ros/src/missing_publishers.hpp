#pragma once
// Which of a node's subscriptions nobody publishes yet: what a client names when it gives up
// waiting for its topics. Includes ROS headers: C++17 only.

#include <ros/subscriber.h>

#include <string>
#include <vector>

namespace bridge::ros1 {

/// The topics of `subscribers` without a publisher, comma-separated ("" when every one has one).
inline std::string missingPublishers(const std::vector<::ros::Subscriber>& subscribers) {
  std::string missing;
  for (const auto& subscriber : subscribers) {
    if (subscriber.getNumPublishers() == 0)
      missing += (missing.empty() ? "" : ", ") + subscriber.getTopic();
  }
  return missing;
}

}  // namespace bridge::ros1
