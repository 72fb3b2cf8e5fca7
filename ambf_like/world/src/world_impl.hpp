#pragma once
// World's private parts (World::Impl), shared by the files that implement World.

#include <BulletCollision/CollisionShapes/btEmptyShape.h>
#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ambf_like/dynamics/bullet_world.hpp"
#include "ambf_like/dynamics/collision_filter.hpp"
#include "ambf_like/world.hpp"
#include "articulation.hpp"
#include "collision_shape_factory.hpp"
#include "soft_body_sleep.hpp"

namespace ambf_like {

namespace detail {
/// A joint together with its namespace-qualified name, for lookups.
struct NamedJoint {
  std::unique_ptr<Joint> joint;
  std::string qualified;
  const std::string& name() const { return joint->name(); }
  const std::string& qualifiedName() const { return qualified; }
};
}  // namespace detail

struct World::Impl {
  WorldSpec settings;
  WorldOptions options;
  /// Per model, its joint trees to be simulated in reduced coordinates.
  std::vector<detail::ArticulationPlan> plans;
  bool articulated;  ///< some model is simulated in reduced coordinates
  detail::BulletWorld bullet;
  btDiscreteDynamicsWorld& world;
  detail::CollisionFilter filter;
  detail::ShapeStore shapes;
  btEmptyShape no_geometry;  ///< for bodies without collision geometry
  std::deque<detail::CollisionTag> tags;
  std::vector<std::unique_ptr<RigidBody>> bodies;
  /// What soft bodies meet instead of a static body's planes (see buildBodyShape).
  std::vector<std::unique_ptr<btCollisionObject>> soft_proxies;
  std::vector<std::unique_ptr<SoftBody>> soft_bodies;
  std::vector<std::unique_ptr<detail::NamedJoint>> joints;
  std::vector<std::unique_ptr<detail::Articulation>> articulations;
  std::vector<std::unique_ptr<Transmission>> transmissions;
  std::vector<std::unique_ptr<CoupledStop>> coupled_stops;
  std::vector<std::unique_ptr<ProximitySensor>> sensors;
  std::vector<std::unique_ptr<ConstraintActuator>> actuators;
  std::optional<detail::SoftBodySleeper> sleeper;  ///< unset when no soft body may sleep
  std::optional<StepGuard> guard;                  ///< set once every model is built
  std::size_t collision_vertices = 0;
  std::size_t collision_primitives = 0;
  std::vector<std::string> warnings;
  double time = 0.0;
  std::uint64_t steps = 0;
  /// Unique among the process's worlds (a saved state names the world it belongs to).
  std::uint64_t id;

  Impl(const SceneSpec& scene, const WorldOptions& opts);
  ~Impl();

  /// Per model, the joint trees its world's Articulation setting puts in reduced coordinates.
  std::vector<detail::ArticulationPlan> planEach(const SceneSpec& scene) const;
  void addModel(const ModelSpec& model, int model_index, MeshLibrary& meshes);
  /// Refuses a soft body whose material needs more substeps than kMaxSoftSubsteps at this
  /// world's step: one step would take as long as thousands.
  /// The last step's contacts (Coulomb forces) of the body with this filter tag; null: all.
  std::vector<Contact> contactsWith(const void* body_tag) const;
  std::vector<SoftContactForce> softContactForcesOn(const void* body_tag) const;
  RigidBody& addBody(const BodySpec& spec, const ModelSpec& model, int model_index,
                     MeshLibrary& meshes, Transform& com_in_body);
  /// The model's joints in its order: those of `trees` as articulations, the others as
  /// constraints.
  void addJoints(const ModelSpec& model, const std::vector<detail::JointTree>& trees,
                 const std::map<std::string, detail::PlacedBody>& by_name);
  std::unique_ptr<detail::JointDynamics> constraintJoint(
      const JointSpec& spec, const std::map<std::string, detail::PlacedBody>& by_name);
  void addJoint(const ModelSpec& model, const JointSpec& spec,
                std::unique_ptr<detail::JointDynamics> dynamics);

  /// Lets the free dynamic bodies sleep, as the world's RigidBodySleep says.
  void letFreeBodiesSleep();

  // The stages of one step, in the order World::step runs them (world_step.cpp).
  void driveJoints(double h);
  void loadArticulations(double h);
  void wakeOrSleepSoftBodies();
  void advanceBullet(double h);
  void readArticulations();
  void castSensors();
  void putRestedSoftBodiesToSleep(double h);
  void readJointCoordinates();
  void collectSdfCells();
  void advanceClock(double h);
  void guardAgainstDivergence();
};

}  // namespace ambf_like
