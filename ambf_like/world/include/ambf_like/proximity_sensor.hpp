#pragma once
// A proximity sensor of the running simulation: rays fixed to a body, cast after every step.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "ambf_like/rigid_body.hpp"
#include "ambf_like/sensor_spec.hpp"

class btCollisionWorld;

namespace ambf_like {

/// What one ray saw at the end of the last step.
struct RayReading {
  bool triggered = false;
  double distance = 0.0;  ///< from the ray's origin to the hit (m); the range when not triggered
  std::string body;       ///< qualified name of the body hit
  Vec3 point = Vec3::Zero();
  Vec3 normal = Vec3::Zero();
  /// When the body is a soft body: the face the ray met and its three nodes (as AMBF's
  /// constraint actuator takes a soft body by the sensed face); -1 otherwise.
  int soft_face = -1;
  std::array<int, 3> face_nodes{-1, -1, -1};
};

/// Each ray reports the nearest body (rigid or soft) it meets within range, never its parent.
class ProximitySensor {
 public:
  ProximitySensor(SensorSpec spec, std::string qualified_name, const RigidBody& parent);

  const std::string& name() const { return spec_.name; }
  const std::string& qualifiedName() const { return qualified_name_; }
  const SensorSpec& spec() const { return spec_; }
  const RigidBody& parent() const { return parent_; }
  const std::vector<RayReading>& readings() const { return readings_; }
  bool triggered() const;
  /// The nearest triggered ray's reading, if any ray is triggered.
  std::optional<RayReading> nearest() const;
  /// A ray's origin and end (at full range) in the world frame, from the parent's pose now.
  std::pair<Vec3, Vec3> rayInWorld(std::size_t index) const;

  /// Casts every ray (World calls this after each step while the sensor is active).
  void sense(const btCollisionWorld& world);
  /// Active (the default, as in AMBF): sensed after every step. Inactive: its rays cost
  /// nothing and its readings say nothing is seen, until it is activated again and stepped.
  bool active() const { return active_; }
  void setActive(bool active);

  /// Its readings and activity (World::saveState).
  struct State {
    std::vector<RayReading> readings;
    bool active = true;
  };
  State state() const { return {readings_, active_}; }
  void restore(const State& state) {
    readings_ = state.readings;
    active_ = state.active;
  }

 private:
  SensorSpec spec_;
  std::string qualified_name_;
  const RigidBody& parent_;
  std::vector<RayReading> readings_;
  bool active_ = true;
};

}  // namespace ambf_like
