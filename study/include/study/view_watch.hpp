#pragma once
// Instruments out of view, as the surgical simulators count them: when each arm's jaws leave the
// picture of the task camera (the camera the trial's video shows), and when they come back.

#include <Eigen/Core>

#include "raven/arm.hpp"
#include "study/trial_events.hpp"
#include "viewer/camera.hpp"

namespace study {

/// Writes "out_of_view" and "in_view" events per arm for one camera and picture size.
class ViewWatch {
 public:
  ViewWatch(const viewer::Camera& camera, int width, int height);

  /// Whether `point` (world frame) lands inside the picture, in front of the camera.
  bool sees(const Eigen::Vector3d& point) const;
  /// The jaws' axes (world frame) at trial time `time` (s).
  void observe(double time, const raven::PerArm<Eigen::Vector3d>& jaws, EventLog& events);

 private:
  viewer::Camera camera_;
  int width_, height_;
  raven::PerArm<bool> out_{};
};

/// A camera whose picture (width / height >= 1) holds the whole ball of `radius` about `centre`:
/// what a task framed on its working volume shows.
viewer::Camera cameraHolding(const Eigen::Vector3d& centre, double radius);

}  // namespace study
