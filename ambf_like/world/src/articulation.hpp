#pragma once
// A model's joint tree in reduced coordinates: one Featherstone btMultiBody on its static root.

#include <BulletDynamics/Featherstone/btMultiBodyLink.h>
#include <LinearMath/btAlignedObjectArray.h>
#include <LinearMath/btVector3.h>

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ambf_like/dynamics/joint_dynamics.hpp"
#include "ambf_like/dynamics/joint_frames.hpp"
#include "ambf_like/dynamics/joint_space_servo.hpp"
#include "ambf_like/rigid_body.hpp"
#include "ambf_like/scene_spec.hpp"
#include "collision_object_motion.hpp"

class btMultiBody;
class btMultiBodyDynamicsWorld;
class btMultiBodyJointLimitConstraint;
class btMultiBodyLinkCollider;

namespace ambf_like::detail {

/// A loaded rigid body and its centre-of-mass frame in its body frame.
struct PlacedBody {
  RigidBody* body = nullptr;
  Transform com_in_body = Transform::Identity();
};

/// Joints hanging from one static body that one btMultiBody can simulate: a branch of
/// revolute, continuous, prismatic or fixed joints whose every body is moving and the child of
/// no other joint, and the parent of no joint outside the branch.
struct JointTree {
  std::string root;                 ///< the static body
  std::vector<std::size_t> joints;  ///< indices into the model's joints, parents first
};

/// Which of a model's joints become articulations, and why the moving bodies left to the
/// constraint formulation are left there.
struct ArticulationPlan {
  std::vector<JointTree> trees;
  std::vector<std::string> left_out;
};
ArticulationPlan planArticulations(const ModelSpec& model);
/// Articulation::Automatic: each model's trees of planArticulations but those that hold a body
/// a constraint actuator hangs from, and none in a scene with Coulomb soft bodies; what stays
/// maximal is no warning.
std::vector<ArticulationPlan> planAutomatically(const std::vector<ModelSpec>& models);

/// One joint tree as a btMultiBody with a fixed base at its static root body. The joints are its
/// degrees of freedom (no constraint rows), so a step costs one articulated-body pass instead
/// of an iterative solve over 5-6 rows per joint. The root stays a static rigid body in the
/// world; every other body's btRigidBody leaves the world and mirrors its link's pose and
/// velocity after each step, so RigidBody reads the same either way. Damped bodies decay as
/// Bullet's damped rigid bodies do (see applyDampingAndOwnGravity), and bodies with a gravity
/// of their own (or their model's) fall by it.
class Articulation {
 public:
  /// The bodies must be at their loaded poses, the tree's moving ones not in `world`;
  /// `step_size` is the world's fixed step.
  Articulation(const ModelSpec& model, const JointTree& tree,
               const std::map<std::string, PlacedBody>& bodies, btMultiBodyDynamicsWorld& world,
               double step_size);
  ~Articulation();
  Articulation(const Articulation&) = delete;
  Articulation& operator=(const Articulation&) = delete;

  /// The coordinate of joint `index` (of the model's joints, one of the tree's) as a degree of
  /// freedom.
  std::unique_ptr<JointDynamics> jointDynamics(std::size_t index);
  /// Applies the joints' torques for the coming step.
  void beforeStep(double dt);
  /// Called once the step's free motion is in the velocities (see ArticulatedDynamicsWorld).
  void afterFreeMotion();
  /// Copies the links' poses and velocities to their bodies; refreshes the inverse inertia.
  void afterStep();

  /// What the articulation's next steps depend on (World::saveState): Bullet's links (their
  /// coordinates and the frames cached from them), the joint velocities, the colliders' motion,
  /// the servo and the inverse inertia it uses.
  struct State {
    std::vector<btMultibodyLink> links;
    std::vector<btScalar> velocities;  ///< the base's six, then the joints'
    std::vector<CollisionObjectMotion> colliders;
    JointSpaceServo servo;
    Eigen::MatrixXd inverse_inertia;
    int steps_since_refresh = 0;
  };
  State state() const;
  void restore(const State& state);

 private:
  struct Link;
  void addLink(int index, const JointSpec& joint, const JointFrames& frames,
               const PlacedBody& parent, const PlacedBody& child, int parent_link);
  void addCollider(int index);
  void refreshInverseInertia();
  void applyDampingAndOwnGravity();
  Eigen::Map<const Eigen::VectorXd> jointVelocities() const;
  /// The joints' coordinates (Bullet's, from the load pose), in degree-of-freedom order.
  const Eigen::VectorXd& jointPositions();

  btMultiBodyDynamicsWorld& world_;
  double step_size_;
  bool damped_ = false;       ///< some link has damping
  bool own_gravity_ = false;  ///< some link has a gravity of its own (or its model's)
  std::unique_ptr<btMultiBody> multibody_;
  std::vector<Link> links_;         ///< in multibody link order (parents first)
  std::vector<int> link_of_joint_;  ///< model joint index -> link
  JointSpaceServo servo_;
  int steps_since_refresh_ = 0;
  // Scratch, sized once: link velocities, and the inverse-inertia queries.
  std::vector<btVector3> omega_;
  std::vector<btVector3> velocity_;
  std::vector<btScalar> unit_force_;
  std::vector<btScalar> acceleration_;
  Eigen::VectorXd position_;  ///< per degree of freedom (jointPositions)
  btAlignedObjectArray<btScalar> scratch_scalars_;
  btAlignedObjectArray<btVector3> scratch_vectors_;
  Eigen::MatrixXd inverse_inertia_;
};

}  // namespace ambf_like::detail
