#pragma once
// The ScenePerception reached over ROS 1: objects' poses from AMBF's object topics (the twin
// node's <namespace><object>/State, ambf_msgs/RigidBodyState) or from a motion tracker's
// geometry_msgs/PoseStamped topics (vrpn_client_ros's /vrpn_client_node/<object>/pose, for the
// physical robot), registered into the robot's world frame. ROS stays behind this header.

#include <Eigen/Geometry>
#include <memory>
#include <string>
#include <vector>

#include "bridge/scene_perception.hpp"

namespace bridge::ros1 {

/// Which messages carry the poses.
enum class PoseSource {
  AmbfObjects,  ///< ambf_msgs/RigidBodyState on <topic_namespace><object>/State
  Tracker,      ///< geometry_msgs/PoseStamped on <topic_namespace><object>/pose
};

/// How the perception reaches its source.
struct RosPerceptionOptions {
  PoseSource source = PoseSource::AmbfObjects;
  /// The topics' prefix: the scene's namespace for AMBF's topics ("/peg_transfer/" for this
  /// project's peg-transfer scene), the tracker node's for a tracker ("/vrpn_client_node/").
  std::string topic_namespace = "/ambf/env/";
  /// The objects to watch (subscribed to when the perception is made).
  std::vector<std::string> objects;
  /// The source's stamps are the platform's simulated clock (a lock-step twin node): update(now)
  /// waits until every object has been reported at `now`. Else stamps are wall time and
  /// update() takes what has arrived (waiting only for an object never heard from yet).
  bool lock_step = false;
  /// Wall seconds to find every object's topic, and to wait for a step's poses (lock-step) or
  /// an object's first.
  double timeout = 10.0;
  /// Wall clock: a sighting older than this (s) is refused (the tracker lost the object).
  double stale_after = 0.5;
  /// The source's frame in the robot's world frame (a tracker's registration); poses are
  /// reported as world_from_source * pose.
  Eigen::Isometry3d world_from_source = Eigen::Isometry3d::Identity();
};

/// Object poses from ROS topics (needs initRos()).
class RosScenePerception final : public ScenePerception {
 public:
  /// Subscribes to every object's topic and waits (timeout) until each has a publisher; throws
  /// PerceptionError naming the topics that have none.
  explicit RosScenePerception(RosPerceptionOptions options);
  ~RosScenePerception() override;
  RosScenePerception(const RosScenePerception&) = delete;
  RosScenePerception& operator=(const RosScenePerception&) = delete;

  void update(double now) override;
  Sighting sight(const std::string& name) const override;

  /// The topic an object's poses come on.
  std::string topicOf(const std::string& object) const;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace bridge::ros1
