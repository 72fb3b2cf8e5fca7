#pragma once
// What a task sees of the scene around the robot: named objects' poses, as a simulator, AMBF's
// object topics or a motion tracker report them. The other half of a task's view next to
// RavenPlatform (which reports the robot itself); backends: twin::WorldPerception (in process),
// bridge::ros1::RosScenePerception (the twin node's object topics, or a tracker's poses).

#include <Eigen/Geometry>
#include <optional>
#include <stdexcept>
#include <string>

namespace bridge {

/// One object as last seen.
struct Sighting {
  double time = 0.0;                                       ///< platform time (s) of the sight
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  ///< in the world frame (m)
  /// A soft object's volume over its rest volume, when the source can tell (a simulation can; a
  /// tracker and AMBF's topics cannot).
  std::optional<double> volume_ratio;
};

/// `pose` as every source reports it: its rotation carried by a unit quaternion (AMBF's object
/// topics, a tracker). A simulator that holds a rotation matrix hands it over this way too, so a
/// task sees the same pose, to the bit, in process and over ROS.
inline Eigen::Isometry3d asReported(const Eigen::Isometry3d& pose) {
  Eigen::Isometry3d reported = pose;
  reported.linear() = Eigen::Quaterniond(pose.linear()).normalized().toRotationMatrix();
  return reported;
}

/// The scene has no object of that name, or it has not been seen (yet, or for too long).
class PerceptionError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A source of object poses.
class ScenePerception {
 public:
  virtual ~ScenePerception() = default;

  /// Takes in what the source has reported up to platform time `now`. A source on a simulated
  /// clock waits (within its timeout) until it has reported every watched object at `now`;
  /// throws PerceptionError when it does not.
  virtual void update(double now) = 0;
  /// The object's latest sighting. Throws PerceptionError when it has none.
  virtual Sighting sight(const std::string& name) const = 0;
};

}  // namespace bridge
