#pragma once
// The running simulation: a Bullet world built from a SceneSpec, stepped at a fixed internal step.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ambf_like/constraint_actuator.hpp"
#include "ambf_like/coupled_stop.hpp"
#include "ambf_like/elastic_solve_stats.hpp"
#include "ambf_like/joint.hpp"
#include "ambf_like/mesh.hpp"
#include "ambf_like/proximity_sensor.hpp"
#include "ambf_like/rigid_body.hpp"
#include "ambf_like/scene_spec.hpp"
#include "ambf_like/soft_body.hpp"
#include "ambf_like/step_guard.hpp"
#include "ambf_like/transmission.hpp"

namespace ambf_like {

/// AMBF's fixed internal physics step (s): 1 ms (reference/adf-format.md, the `-t` flag).
inline constexpr double kAmbfStepSize = 0.001;

/// How a World is run, which no file says: AMBF takes its step from the command line (`-t`).
/// Every physics setting lives in the SceneSpec's WorldSpec (the world file's, or set there).
struct WorldOptions {
  double step_size = kAmbfStepSize;  ///< fixed internal step (s)
};

/// One contact point between two bodies after the last step.
struct Contact {
  std::string body_a;  ///< qualified names
  std::string body_b;
  Vec3 position_on_b = Vec3::Zero();
  Vec3 normal_on_b = Vec3::Zero();       ///< points from b towards a
  double distance = 0.0;                 ///< negative when penetrating
  double normal_impulse = 0.0;           ///< on a, along normal_on_b (N s)
  Vec3 friction_impulse = Vec3::Zero();  ///< on a, tangential (N s)
  bool soft = false;  ///< a soft body's node (a) on a rigid body: no impulses recorded
};

/// The force a rigid body put on one node of a soft body with Coulomb contacts in the last step.
struct SoftContactForce {
  std::string soft_body;  ///< qualified names
  std::string rigid_body;
  Vec3 position = Vec3::Zero();        ///< the node
  Vec3 normal = Vec3::Zero();          ///< of the rigid surface, towards the node
  Vec3 normal_force = Vec3::Zero();    ///< on the node (N)
  Vec3 friction_force = Vec3::Zero();  ///< on the node, tangential (N)
};

/// A World's state between two steps (World::saveState); opaque, restored only into the World
/// that saved it.
class WorldState;

/// Mutable simulation state built once from an immutable SceneSpec (MuJoCo's model/data split).
/// Bodies and joints are indexed in load order; names may be plain (if unique) or qualified
/// with their model namespace.
class World {
 public:
  /// Throws LoadError if a mesh cannot be read or a soft-body fixed node does not exist.
  World(const SceneSpec& scene, MeshLibrary& meshes, WorldOptions options = {});
  ~World();
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  /// Advances one fixed internal step: joint controllers, then Bullet, then the guard: throws
  /// SimulationDiverged (naming the body, node, step and time) when a body or node is not
  /// finite, has left the world's bounds or moves faster than the scene allows (StepGuard).
  void step();
  void step(std::uint64_t count);

  /// Everything the next steps depend on: the rigid bodies' poses and velocities, the joints'
  /// commands and controllers, the articulations' coordinates, velocities, servos and engaged
  /// limits, the soft bodies' nodes, faces, anchors and contacts, the contact manifolds with
  /// their impulses (the solver's warm start), the soft-body solvers' warm starts, sleep, the
  /// sensors' readings and the clock. Saving also rebuilds the collision caches (broadphase
  /// trees and pairs, the soft bodies' trees) in a canonical order, as restoring does, so the
  /// steps after a save and after any restore of it are the same, bit for bit.
  std::shared_ptr<const WorldState> saveState();
  /// Puts the world back to `state`. Throws std::invalid_argument for a state of another world,
  /// std::logic_error when a constraint actuator holds otherwise than it did then.
  void restoreState(const WorldState& state);

  double time() const;
  std::uint64_t stepCount() const;
  double stepSize() const;
  const WorldSpec& settings() const;

  std::size_t jointCount() const;
  Joint& joint(std::size_t index);
  const Joint& joint(std::size_t index) const;
  /// Throws std::out_of_range naming the joint when it does not exist or is ambiguous.
  Joint& joint(std::string_view name);
  std::optional<std::size_t> findJoint(std::string_view name) const;

  std::size_t bodyCount() const;
  RigidBody& body(std::size_t index);
  const RigidBody& body(std::size_t index) const;
  RigidBody& body(std::string_view name);
  const RigidBody& body(std::string_view name) const;

  std::size_t softBodyCount() const;
  SoftBody& softBody(std::size_t index);
  const SoftBody& softBody(std::size_t index) const;
  SoftBody& softBody(std::string_view name);
  const SoftBody& softBody(std::string_view name) const;

  /// Proximity sensors (cast after every step) and constraint actuators, by load order or by
  /// (qualified) name; unknown or ambiguous names throw std::out_of_range.
  std::size_t sensorCount() const;
  ProximitySensor& sensor(std::size_t index);
  ProximitySensor& sensor(std::string_view name);
  std::size_t actuatorCount() const;
  ConstraintActuator& actuator(std::size_t index);
  ConstraintActuator& actuator(std::string_view name);

  /// Every contact point of the last step, rigid-rigid and soft-rigid.
  std::vector<Contact> contacts() const;
  /// Only those that touch the rigid body `body` (named as body() takes it, and throwing the same
  /// way): what a per-step reader of one body's contacts should call.
  std::vector<Contact> contacts(std::string_view body) const;
  /// Per node, the forces of the last step's Coulomb contacts (soft bodies with
  /// `contact friction: coulomb`); the rigid body felt the opposite.
  std::vector<SoftContactForce> softContactForces() const;
  /// Only those from the rigid body `rigid_body`.
  std::vector<SoftContactForce> softContactForces(std::string_view rigid_body) const;
  /// False as soon as any pose, velocity or soft-body node is NaN or infinite.
  bool isFinite() const;
  /// The bounds and speed every step is held to.
  const StepGuard& guard() const;
  /// What the implicit solve of a soft body with a material took so far (zeros without one).
  ElasticSolveStats elasticSolveStats(const SoftBody& body) const;
  /// Joint trees simulated in reduced coordinates, one per branch from a static body (see
  /// Articulation).
  std::size_t articulationCount() const;
  /// Puts motors behind joints of one articulation (see TransmissionSpec); the World keeps it.
  /// Throws std::invalid_argument naming the field or joint when the sizes disagree, a value is
  /// not finite, an inertia is not positive, a joint is not of one articulation's coordinates
  /// (maximal coordinates, a fixed joint, another articulation) or that articulation already has
  /// a transmission; std::out_of_range for an unknown joint.
  Transmission& addTransmission(const TransmissionSpec& spec);
  /// Puts a stop on a sum of joint coordinates of one articulation (see CoupledStopSpec); the
  /// World keeps it. Throws std::invalid_argument naming the joint when the sizes disagree, a
  /// value is not finite or a joint is not of one articulation's coordinates; std::out_of_range
  /// for an unknown joint.
  CoupledStop& addCoupledStop(const CoupledStopSpec& spec);
  /// What the world built otherwise than its files asked, and why (e.g. a model asked to be
  /// articulated that stays in maximal coordinates).
  const std::vector<std::string>& warnings() const;
  /// Vertices of every mesh collision shape (primitives count as none).
  std::size_t collisionVertexCount() const;
  /// Primitive collision shapes (boxes, spheres, cylinders, capsules, cones, planes).
  std::size_t collisionPrimitiveCount() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ambf_like
