#pragma once
// The peg-transfer scene's named cameras (overview, left-task, right-task, grasper-left,
// grasper-right: scenario/task_views.hpp) rendered headless at a camera's frame rate on the
// twin's clock and published as a camera driver would (sensor_msgs/Image, rgb8, on
// cameras/<view>/image_raw with '-' written '_'; with depth, as an RGB-D camera's driver also
// publishes it, 32FC1 in m on cameras/<view>/depth/image_raw), so a policy that sees reaches the
// twin node as it would reach the robot's cameras.

#include <memory>
#include <string>
#include <vector>

#include "ambf_like/world.hpp"
#include "bridge/ros/ros_image_publisher.hpp"

namespace scenario {
class PegCameras;
}

namespace twin::ros1 {

/// Which views, at what size and rate.
struct CameraTopicOptions {
  std::vector<std::string> views;
  int width = 128;
  int height = 96;
  double rate = 30.0;  ///< frames per second of the twin's clock
  bool depth = false;  ///< each view's depth image too (an RGB-D camera)
  /// How that depth reads (viewer::StereoDepthErrors): exact by default, or as a stereo RGB-D
  /// camera reads it, with its RMS error at 1 m (m), its scale bias and its baseline (m).
  double depth_noise = 0.0, depth_scale = 1.0, depth_baseline = 0.0;
};

/// Renders and publishes the views (needs initRos() and a headless OpenGL).
class CameraTopics {
 public:
  /// Throws std::invalid_argument for an unknown view (listing them) or a rate that is not
  /// positive, viewer::NoDisplay when no headless OpenGL can be made.
  CameraTopics(const ambf_like::World& world, CameraTopicOptions options);
  ~CameraTopics();
  CameraTopics(const CameraTopics&) = delete;
  CameraTopics& operator=(const CameraTopics&) = delete;

  /// Renders and publishes every view when a frame is due at twin time `now`; `stamp` goes in
  /// the images' headers.
  void update(const ambf_like::World& world, double now, double stamp);

  /// The topic a view's colour images are published on, relative to the node's namespace.
  static std::string topicOf(const std::string& view);
  /// The topic its depth images are published on.
  static std::string depthTopicOf(const std::string& view);

 private:
  CameraTopicOptions options_;
  std::unique_ptr<scenario::PegCameras> cameras_;
  bridge::ros1::RosImagePublisher publisher_;  ///< colour topics, then depth topics
  double next_frame_ = 0.0;
};

}  // namespace twin::ros1
