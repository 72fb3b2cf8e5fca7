#pragma once
// A whole scene as plain data: the world settings and every loaded model (immutable after loading).

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "ambf_like/body_spec.hpp"
#include "ambf_like/joint_spec.hpp"
#include "ambf_like/sensor_spec.hpp"
#include "ambf_like/soft_body_spec.hpp"

namespace ambf_like {

/// One multibody file (ADF or URDF): its bodies, joints and soft bodies.
struct ModelSpec {
  std::filesystem::path file;
  std::string name_space;
  std::vector<BodySpec> bodies;
  std::vector<JointSpec> joints;
  std::vector<SoftBodySpec> soft_bodies;
  std::vector<SensorSpec> sensors;
  std::vector<ActuatorSpec> actuators;
  bool ignore_inter_collision =
      false;                    ///< no collisions between any two rigid bodies of this model
  std::optional<Vec3> gravity;  ///< model-wide override of the world gravity
};

/// When resting soft bodies stop being simulated. Bullet deactivates resting rigid bodies but
/// never soft ones; a sleeping soft body costs nothing until a moving body comes near it.
struct SoftBodySleep {
  bool enabled = true;
  /// A body rests while every node stays within `distance` (m) of where it was `time` (s)
  /// ago, and then falls asleep. Nodes in contact jitter by a few mm/s, so speed is no test.
  double distance = 0.001;
  double time = 0.5;
  /// A body moving faster than distance / time this close (m) to a sleeper's bounds wakes it.
  double wake_distance = 0.01;
};

/// When resting free rigid bodies (those no joint holds) stop being simulated: Bullet's own
/// island deactivation, at speeds 160 times below Bullet's defaults (0.8 m/s, 1 rad/s). A body
/// whose speeds stay below these for 2 s (Bullet's deactivation time) sleeps with its island; a
/// moving body that touches it or an awake soft body in contact with it (both Bullet's), or an
/// actuator that takes it wakes it. Jointed bodies never sleep: a command can come at any step.
struct RigidBodySleep {
  bool enabled = true;
  double linear_speed = 0.005;  ///< m/s
  double angular_speed = 0.05;  ///< rad/s
};

/// How jointed models are simulated. Maximal: every body is a rigid body and every joint a
/// constraint the solver iterates on (AMBF's way). Reduced: each branch of joints hanging from a
/// static body (revolute, continuous, prismatic or fixed, each body the child of one joint)
/// becomes a Featherstone articulation whose joints are its coordinates; the rest stays maximal,
/// and the World says why (World::warnings). Automatic (the default): reduced wherever it is the
/// same physics, maximal where reduced coordinates cannot carry the scene: each branch holding a
/// body a constraint actuator hangs from (it attaches bodies to rigid bodies).
enum class Articulation { Automatic, Maximal, Reduced };

/// World-file settings that matter to the physics.
struct WorldSpec {
  std::filesystem::path file;  ///< empty when defaults are used
  std::string name_space = "/ambf/env/";
  Vec3 gravity{0.0, 0.0, -9.81};
  int max_iterations = 10;  ///< Bullet max sub-steps per outer iteration
  /// This simulator's own settings (an `ambf_like:` block AMBF ignores); a program changes them
  /// here, on the spec, before it builds the World (their one home).
  /// Sequential-impulse iterations per step; unset: Bullet's 10.
  std::optional<int> solver_iterations;
  /// Soft-vs-rigid signed-distance grid (m); unset: 0.01. Bullet's own 0.25 m cannot represent
  /// rigid parts thinner than a few voxels (a 10 mm board lets soft bodies sink through it).
  std::optional<double> sdf_voxel_size;
  SoftBodySleep soft_body_sleep;
  RigidBodySleep rigid_body_sleep;
  Articulation articulation = Articulation::Automatic;
};

/// Everything needed to build a simulation.
struct SceneSpec {
  WorldSpec world;
  std::vector<ModelSpec> models;
};

}  // namespace ambf_like
