#pragma once
// AMBF's sensors and actuators as plain data: proximity (ray-cast) sensors with an array or a
// parametric fan of rays, and constraint actuators.

#include <string>
#include <vector>

#include "ambf_like/load_error.hpp"
#include "ambf_like/transform.hpp"

namespace ambf_like {

/// One ray of a proximity sensor, in the sensor's frame (its `location` on the parent body).
struct SensorRay {
  Vec3 origin = Vec3::Zero();
  Vec3 direction = Vec3::UnitX();  ///< unit
};

/// PROXIMITY (AMBF's RAYTRACER) senses; RESISTANCE senses the same way (its resistive forces
/// are accepted, not simulated).
enum class SensorType { Proximity, Resistance };

/// A sensor fixed to a rigid body.
struct SensorSpec {
  std::string name;
  std::string parent;  ///< a rigid body of the same model
  SensorType type = SensorType::Proximity;
  Transform location = Transform::Identity();  ///< sensor frame in the parent body frame
  double range = 0.0;                          ///< m, along every ray
  std::vector<SensorRay> rays;
  SourceRef where;
};

/// A constraint actuator: attaches a body to its parent, where the body is, until released.
struct ActuatorSpec {
  std::string name;
  std::string parent;                          ///< a rigid body of the same model
  Transform location = Transform::Identity();  ///< the attachment point in the parent frame
  /// Largest impulse (N s) the attachment applies in one step; 0: unlimited (Bullet's default).
  double max_impulse = 0.0;
  double tau = 0.3;  ///< how fast the attachment closes its error per step (Bullet's default)
  SourceRef where;
};

}  // namespace ambf_like
