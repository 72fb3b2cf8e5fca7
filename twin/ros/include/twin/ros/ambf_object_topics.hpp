#pragma once
// A world's bodies, sensors and actuators on AMBF's own topics, so AMBF's clients (SRC's needle
// grasp, its Python client) and a task's ScenePerception reach them: each body's
// ambf_msgs/RigidBodyState (soft bodies too, as their shape-matched frame), each sensor's
// ambf_msgs/SensorState and each actuator's ambf_msgs/ActuatorState on <qualified name>/State,
// and ambf_msgs/ActuatorCmd taken from <qualified name>/Command (qualified names start with the
// model's namespace, /ambf/env/ by default, as AMBF's topics do). A topic nobody subscribes to
// costs nothing.

#include <memory>

#include "ambf_like/world.hpp"

namespace twin::ros1 {

/// Advertises and subscribes for every body, sensor and actuator of a world (needs initRos()).
class AmbfObjectTopics {
 public:
  /// `simulated_stamps`: headers carry the simulated time (a lock-step node, whose other topics
  /// do too); else the wall clock, as AMBF's do.
  AmbfObjectTopics(ambf_like::World& world, bool simulated_stamps);
  ~AmbfObjectTopics();
  AmbfObjectTopics(const AmbfObjectTopics&) = delete;
  AmbfObjectTopics& operator=(const AmbfObjectTopics&) = delete;

  /// Applies the actuator commands that have arrived (in order), then publishes every sensor's
  /// and actuator's state at simulated time `sim_time`. Call it after a step. A command naming a
  /// body that does not exist, or one no actuator can hold, is logged and changes nothing.
  void update(double sim_time);

  std::size_t bodyTopics() const;
  std::size_t sensorTopics() const;
  std::size_t actuatorTopics() const;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace twin::ros1
