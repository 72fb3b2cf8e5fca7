#pragma once
// Subscription hints for the robot's 1 kHz topics. Includes ROS headers: C++17 only.

#include <ros/transport_hints.h>

namespace bridge::ros1 {

/// TCP without Nagle's algorithm: with it, each small 1 kHz message (and each lock-step reply)
/// can wait tens of milliseconds for the next one.
inline ::ros::TransportHints lowLatency() {
  return ::ros::TransportHints().tcpNoDelay();
}

}  // namespace bridge::ros1
