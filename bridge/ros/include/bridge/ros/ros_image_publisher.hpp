#pragma once
// Colour images on ROS 1 topics as a camera driver publishes them (sensor_msgs/Image, rgb8): the
// twin node's rendered cameras. ROS stays behind this header.

#include <memory>
#include <string>
#include <vector>

#include "bridge/camera_frame.hpp"

namespace bridge::ros1 {

/// One publisher per camera topic (names relative to the node's namespace). Needs initRos().
class RosImagePublisher {
 public:
  /// `frame_ids`: each image's header.frame_id (the camera's name), one per topic.
  RosImagePublisher(const std::vector<std::string>& topics,
                    const std::vector<std::string>& frame_ids);
  ~RosImagePublisher();
  RosImagePublisher(const RosImagePublisher&) = delete;
  RosImagePublisher& operator=(const RosImagePublisher&) = delete;

  /// Publishes `frame` on camera `camera`'s topic, stamped with frame.time. Throws
  /// std::invalid_argument for a frame whose bytes are not width x height x 3.
  void publish(std::size_t camera, const CameraFrame& frame);

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace bridge::ros1
