#pragma once
// Test helpers for an arm touching things in the twin: motors without friction, an obstacle in
// the scene, which bodies each joint moves, and what their contacts put on the joints.

#include <string>
#include <vector>

#include "ambf_like/scene_spec.hpp"
#include "ambf_like/shape_spec.hpp"
#include "twin/twin_platform.hpp"

namespace test_support {

/// The shipped mechanics without friction, offset or gravity error: at rest the motors then carry
/// the links' weight alone.
twin::TwinOptions frictionlessMotors();

/// One encoder count of `joint` in joint units: how far past a stop a reading may land.
double countInJoint(const twin::DriveTrain& drive, int joint);

/// Our Raven-II with one static obstacle (`/test/obstacle`) of `shape` at `pose` (world), and no
/// rolling friction anywhere: Bullet's rolling friction puts a couple on a pressed contact (AMBF's
/// default 0.01 m times the normal force) that no contact point reports, and the statics checked
/// here are of point forces.
twin::TwinOptions withObstacle(const twin::TwinOptions& base,
                               const ambf_like::PrimitiveShape& shape,
                               const ambf_like::Transform& pose, double friction);

/// `arm`'s joints and, per joint, the bodies it moves (its child and everything beyond).
struct ArmChain {
  std::vector<const ambf_like::Joint*> joints;
  std::vector<std::vector<std::string>> moves;  ///< qualified body names, per joint
};
ArmChain chainOf(twin::TwinPlatform& twin, raven::Arm arm);

/// J^T F: the joint loads (N m, N) the last step's contacts on `arm`'s bodies put on its joints,
/// each contact force taken about the joint's axis through its pivot as the World has them now.
raven::ArmJoints contactLoads(twin::TwinPlatform& twin, raven::Arm arm);

/// Whether any body that `joint` of `arm` moves presses on something.
bool touching(twin::TwinPlatform& twin, raven::Arm arm, int joint);

/// The force (N, world) the last step's contacts put on the body `name`.
Eigen::Vector3d contactForceOn(const ambf_like::World& world, const std::string& name);

}  // namespace test_support
