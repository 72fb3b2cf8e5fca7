#pragma once
// Colour images taken in from ROS 1 camera topics (sensor_msgs/Image: rgb8, bgr8, rgba8, bgra8
// or mono8, as camera drivers publish them): the physical robot's cameras or the twin node's
// rendered ones. Images arrive on a thread of their own; a message that is not a whole image is
// refused, naming its topic and what is wrong. ROS stays behind this header.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "bridge/camera_frame.hpp"

namespace bridge::ros1 {

/// The camera topics, and how long to wait for them.
struct RosCameraOptions {
  std::vector<std::string> topics;
  double timeout = 10.0;  ///< wall s to find each topic's publisher, and to wait for an image
};

/// The latest image of each topic (needs initRos()).
class RosCameraImages {
 public:
  /// Subscribes and waits (timeout) until every topic has a publisher; throws std::runtime_error
  /// naming the topics that have none.
  explicit RosCameraImages(RosCameraOptions options);
  ~RosCameraImages();
  RosCameraImages(const RosCameraImages&) = delete;
  RosCameraImages& operator=(const RosCameraImages&) = delete;

  /// Images taken in on camera `camera` so far (refused ones not counted).
  std::uint64_t received(std::size_t camera) const;
  /// The latest image of camera `camera` once more than `after` have been taken in (received()
  /// before a move: an image of the scene after it). Throws std::runtime_error naming the topic
  /// (and why its last message was refused, if it was) when none comes within the timeout.
  CameraFrame latest(std::size_t camera, std::uint64_t after) const;
  const std::vector<std::string>& topics() const;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace bridge::ros1
