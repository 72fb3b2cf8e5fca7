#pragma once
// Between camera frames and sensor_msgs/Image. Reading a message checks that it is a whole image
// and says what is wrong. Includes ROS 1 message headers: C++17 translation units only.

#include <sensor_msgs/Image.h>

#include <string>

#include "bridge/camera_frame.hpp"
#include "bridge/ros/ros_conversions.hpp"

namespace bridge::ros1 {

/// An rgb8 image of `frame`, stamped with frame.time. Throws std::invalid_argument when its
/// bytes are not width x height x 3.
sensor_msgs::Image toImage(const CameraFrame& frame, const std::string& frame_id);
/// The frame of an rgb8, bgr8, rgba8, bgra8 or mono8 image (any row padding): refused when the
/// encoding is another, a size is zero or its data is shorter than step x height or the step
/// shorter than a row.
Parsed<CameraFrame> frameFromImage(const sensor_msgs::Image& message);

}  // namespace bridge::ros1
