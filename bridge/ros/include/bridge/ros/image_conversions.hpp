#pragma once
// Between camera frames and sensor_msgs/Image. Reading a message checks that it is a whole image
// and says what is wrong. Includes ROS 1 message headers: C++17 translation units only.

#include <sensor_msgs/Image.h>

#include <string>

#include "bridge/camera_frame.hpp"
#include "bridge/ros/ros_conversions.hpp"

namespace bridge::ros1 {

/// An rgb8 image of `frame`, or a 32FC1 one (m, REP 118) of a depth frame, stamped with
/// frame.time. Throws std::invalid_argument when it has not width x height pixels.
sensor_msgs::Image toImage(const CameraFrame& frame, const std::string& frame_id);
/// The frame of an rgb8, bgr8, rgba8, bgra8 or mono8 image, or the depth frame of a 32FC1 (m)
/// or 16UC1 (mm, 0: no reading) one (REP 118; any row padding, either byte order): refused when
/// the encoding is another, a size is zero or its data is shorter than step x height or the
/// step shorter than a row.
Parsed<CameraFrame> frameFromImage(const sensor_msgs::Image& message);

}  // namespace bridge::ros1
