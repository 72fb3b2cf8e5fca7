#include "articulation.hpp"

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "ambf_like/bullet_conversions.hpp"
#include "ambf_like/dynamics/bullet_world.hpp"
#include "ambf_like/dynamics/collision_filter.hpp"
#include "ambf_like/dynamics/joint_limit_constraint.hpp"
#include "ambf_like/dynamics/multibody_joint.hpp"
#include "ambf_like/dynamics/multibody_weight.hpp"

namespace ambf_like::detail {

namespace {

/// Steps between refreshes of the joint-space inverse inertia (one articulated-body pass per
/// joint). In 10 ms a joint at 3 rad/s (the Raven's speed limit) turns 0.03 rad: it barely moves.
constexpr int kInertiaRefreshSteps = 10;

bool isArticulableJoint(JointType type) {
  return type == JointType::Revolute || type == JointType::Continuous ||
         type == JointType::Prismatic || type == JointType::Fixed;
}

/// The joint's coordinate in the bodies' loaded poses, as its Bullet constraint reads it.
double coordinateAtLoad(const JointSpec& joint, const Transform& frame_a_in_world,
                        const Transform& frame_b_in_world) {
  const Transform relative = frame_a_in_world.inverse() * frame_b_in_world;
  switch (joint.type) {
    case JointType::Revolute:
    case JointType::Continuous:
      return std::atan2(relative.linear()(1, 0), relative.linear()(0, 0));
    case JointType::Prismatic:
      return relative.translation().x();
    default:
      return 0.0;
  }
}

/// The rate c whose force -c m v takes a free body's velocity down by Bullet's rigid-body
/// damping factor (1 - d)^h in one step of h: c = (1 - (1 - d)^h) / h.
double dampingRate(double damping, double step_size) {
  const double kept = std::pow(1.0 - std::clamp(damping, 0.0, 1.0), step_size);
  return (1.0 - kept) / step_size;
}

const BodySpec* findBody(const ModelSpec& model, const std::string& name) {
  for (const auto& body : model.bodies) {
    if (body.name == name) return &body;
  }
  return nullptr;  // another model's
}

/// Why the joint tree grown from `tree`'s first joint cannot be an articulation, or nothing
/// (and the tree is complete) when it can.
std::optional<std::string> growTree(const ModelSpec& model,
                                    const std::map<std::string, int>& parents_of, JointTree& tree) {
  for (std::size_t k = 0; k < tree.joints.size(); ++k) {
    const JointSpec& joint = model.joints[tree.joints[k]];
    const BodySpec* child = findBody(model, joint.child);
    if (!isArticulableJoint(joint.type))
      return "joint '" + joint.name + "' is not revolute, continuous, prismatic or fixed";
    if (child == nullptr || child->mass == 0.0)
      return "joint '" + joint.name + "' ends on a static body or another model's";
    if (parents_of.at(child->name) != 1)
      return "body '" + child->name + "' is the child of more than one joint";
    for (std::size_t j = 0; j < model.joints.size(); ++j) {
      if (model.joints[j].parent == child->name) tree.joints.push_back(j);
    }
  }
  return std::nullopt;
}

/// The most degrees of freedom one articulation gets. Its joint-space servo keeps the dense
/// inverse inertia (memory and work per step growing with their square: a 2,000-joint chain
/// takes 0.3 GB and steps at 21 Hz, a 20,000-joint one would need 30 GB); beyond this, the
/// constraint formulation's cost, linear in the joints, is the smaller.
constexpr std::size_t kMostDegreesOfFreedom = 64;

/// Why `tree` is too large to be one articulation, or nothing.
std::optional<std::string> tooLarge(const ModelSpec& model, const JointTree& tree) {
  const auto dofs = static_cast<std::size_t>(
      std::count_if(tree.joints.begin(), tree.joints.end(),
                    [&](std::size_t j) { return model.joints[j].type != JointType::Fixed; }));
  if (dofs <= kMostDegreesOfFreedom) return std::nullopt;
  return std::to_string(dofs) + " moving joints, more than the " +
         std::to_string(kMostDegreesOfFreedom) +
         " one articulation takes (its joint-space solve grows with their square)";
}

}  // namespace

ArticulationPlan planArticulations(const ModelSpec& model) {
  std::map<std::string, int> parents_of;
  for (const auto& body : model.bodies) parents_of[body.name] = 0;
  for (const auto& joint : model.joints) ++parents_of[joint.child];
  ArticulationPlan plan;
  std::set<std::string> placed;  // moving bodies in a tree
  for (std::size_t j = 0; j < model.joints.size(); ++j) {
    const JointSpec& joint = model.joints[j];
    const BodySpec* parent = findBody(model, joint.parent);
    const BodySpec* child = findBody(model, joint.child);
    if (parent == nullptr || parent->mass != 0.0 || child == nullptr || child->mass == 0.0)
      continue;  // not a branch from a static body
    JointTree tree{parent->name, {j}};
    auto why = growTree(model, parents_of, tree);
    if (!why) why = tooLarge(model, tree);
    if (why) {
      plan.left_out.push_back("the branch from '" + parent->name + "' through joint '" +
                              joint.name + "': " + *why);
      continue;
    }
    for (const std::size_t k : tree.joints) placed.insert(model.joints[k].child);
    plan.trees.push_back(std::move(tree));
  }
  for (const auto& body : model.bodies) {
    const bool jointed = std::any_of(model.joints.begin(), model.joints.end(), [&](const auto& j) {
      return j.parent == body.name || j.child == body.name;
    });
    // A child of a joint that is in no tree is in a branch already reported, or below a body
    // that is.
    const bool has_parent_joint = parents_of.at(body.name) > 0;
    if (body.mass != 0.0 && jointed && !has_parent_joint && !placed.contains(body.name))
      plan.left_out.push_back("body '" + body.name +
                              "' is no joint's child, so no branch from a static body reaches it");
  }
  return plan;
}

namespace {

/// The qualified names of the bodies the models' actuators may hang from: a body of the
/// actuator's own model by its name, or any model's by its qualified or plain name (as World
/// resolves them; every body that could be meant).
std::set<std::string> actuatorParents(const std::vector<ModelSpec>& models) {
  std::set<std::string> out;
  for (const auto& model : models) {
    for (const auto& actuator : model.actuators) {
      if (findBody(model, actuator.parent) != nullptr) {
        out.insert(model.name_space + actuator.parent);
        continue;
      }
      out.insert(actuator.parent);
      for (const auto& other : models) {
        if (findBody(other, actuator.parent) != nullptr)
          out.insert(other.name_space + actuator.parent);
      }
    }
  }
  return out;
}

}  // namespace

std::vector<ArticulationPlan> planAutomatically(const std::vector<ModelSpec>& models) {
  std::vector<ArticulationPlan> plans(models.size());
  const auto held = actuatorParents(models);
  for (std::size_t i = 0; i < models.size(); ++i) {
    const ModelSpec& model = models[i];
    for (auto& tree : planArticulations(model).trees) {
      const bool holds = std::any_of(tree.joints.begin(), tree.joints.end(), [&](std::size_t j) {
        return held.contains(model.name_space + model.joints[j].child);
      });
      if (!holds) plans[i].trees.push_back(std::move(tree));
    }
  }
  return plans;
}

struct Articulation::Link {
  RigidBody* body = nullptr;
  /// Bullet's rigid-body damping as rates (1/s): see applyDampingAndOwnGravity.
  double linear_damping_rate = 0.0;
  double angular_damping_rate = 0.0;
  /// What the body's own gravity (or its model's) adds to the world's pull on it (N).
  btVector3 own_gravity_force{0, 0, 0};
  std::unique_ptr<btMultiBodyLinkCollider> collider;
  std::unique_ptr<btMultiBodyJointLimitConstraint> limit;
  JointType type = JointType::Fixed;
  double coordinate_at_load = 0.0;
};

Articulation::Articulation(const ModelSpec& model, const JointTree& tree,
                           const std::map<std::string, PlacedBody>& bodies,
                           btMultiBodyDynamicsWorld& world, double step_size)
    : world_(world),
      step_size_(step_size),
      link_of_joint_(model.joints.size(), -1),
      servo_(static_cast<int>(std::count_if(tree.joints.begin(), tree.joints.end(), [&](auto j) {
        return model.joints[j].isSingleAxis();
      }))) {
  const auto& order = tree.joints;
  std::map<std::string, int> link_of_body{{tree.root, -1}};
  for (std::size_t link = 0; link < order.size(); ++link) {
    link_of_joint_[order[link]] = static_cast<int>(link);
    link_of_body[model.joints[order[link]].child] = static_cast<int>(link);
  }
  const RigidBody& root = *bodies.at(tree.root).body;

  multibody_ = std::make_unique<btMultiBody>(static_cast<int>(order.size()), 0.0,
                                             btVector3(0, 0, 0), true, false);
  multibody_->setBaseWorldTransform(root.bullet().getCenterOfMassTransform());
  links_.resize(order.size());
  for (const std::size_t j : order) {
    const auto& joint = model.joints[j];
    const auto& parent = bodies.at(joint.parent);
    const auto& child = bodies.at(joint.child);
    const auto frames = computeJointFrames(joint, parent.com_in_body, parent.body->spec().scale,
                                           child.com_in_body, child.body->spec().scale);
    addLink(link_of_joint_[j], joint, frames, parent, child, link_of_body.at(joint.parent));
    if (joint.parent == tree.root && joint.ignore_inter_collision) {
      // Bullet keeps a link from its parent link only; the root is no link.
      static_cast<CollisionTag*>(child.body->bullet().getUserPointer())
          ->jointed.push_back(static_cast<const CollisionTag*>(root.bullet().getUserPointer()));
    }
    if (const auto gravity =
            child.body->spec().gravity ? child.body->spec().gravity : model.gravity) {
      // Bullet pulls every link down by the world's gravity; this makes up the difference.
      links_[static_cast<std::size_t>(link_of_joint_[j])].own_gravity_force =
          child.body->mass() * (toBt(*gravity) - world.getGravity());
      own_gravity_ = true;
    }
  }
  multibody_->finalizeMultiDof();
  omega_.resize(links_.size() + 1);  // the base's first
  velocity_.resize(links_.size() + 1);
  const auto dofs = static_cast<std::size_t>(multibody_->getNumDofs());
  unit_force_.assign(6 + dofs, 0.0);  // the base's six first
  acceleration_.assign(6 + dofs, 0.0);
  inverse_inertia_.resize(multibody_->getNumDofs(), multibody_->getNumDofs());
  position_ = Eigen::VectorXd::Zero(multibody_->getNumDofs());
  multibody_->setLinearDamping(0.0);
  multibody_->setAngularDamping(0.0);
  multibody_->setHasSelfCollision(!model.ignore_inter_collision);
  // Jointed bodies never sleep (a command can come at any step), and a sleeping multibody is
  // not woken by its joints' torques.
  multibody_->setCanSleep(false);
  // Bullet clamps a multibody's coordinate speeds at 100 (rad/s or m/s), which would hide a
  // runaway joint from the StepGuard; its rigid bodies' clamp (a quarter turn a step) instead.
  multibody_->setMaxCoordinateVelocity(M_PI_2 / step_size_);
  world_.addMultiBody(multibody_.get());

  for (std::size_t i = 0; i < links_.size(); ++i) addCollider(static_cast<int>(i));
  btAlignedObjectArray<btQuaternion> rotations;
  btAlignedObjectArray<btVector3> offsets;
  multibody_->updateCollisionObjectWorldTransforms(rotations, offsets);
  // The articulated-body pass caches what the inertia queries need; at dt = 0 it moves nothing.
  btAlignedObjectArray<btScalar> scalars;
  btAlignedObjectArray<btVector3> vectors;
  btAlignedObjectArray<btMatrix3x3> matrices;
  multibody_->computeAccelerationsArticulatedBodyAlgorithmMultiDof(0.0, scalars, vectors, matrices,
                                                                   false, false, false);
  refreshInverseInertia();
}

void Articulation::addCollider(int index) {
  auto& link = links_[static_cast<std::size_t>(index)];
  const btRigidBody& mirror = link.body->bullet();
  link.collider = std::make_unique<btMultiBodyLinkCollider>(multibody_.get(), index);
  link.collider->setCollisionShape(const_cast<btCollisionShape*>(mirror.getCollisionShape()));
  link.collider->setWorldTransform(mirror.getCenterOfMassTransform());
  link.collider->setFriction(mirror.getFriction());
  link.collider->setRollingFriction(mirror.getRollingFriction());
  link.collider->setRestitution(mirror.getRestitution());
  link.collider->setUserPointer(mirror.getUserPointer());  // the same collision filter tag
  multibody_->getLink(index).m_collider = link.collider.get();
  world_.addCollisionObject(link.collider.get(), btBroadphaseProxy::DefaultFilter,
                            btBroadphaseProxy::AllFilter);
  keepBroadphaseBalanced(world_);
  // Sizes its rows for the now final degrees of freedom; the joint engages it near a bound.
  if (link.limit) link.limit->finalizeMultiDof();
}

Articulation::~Articulation() {
  for (auto& link : links_) {
    if (link.limit) world_.removeMultiBodyConstraint(link.limit.get());
    world_.removeCollisionObject(link.collider.get());
  }
  world_.removeMultiBody(multibody_.get());
}

void Articulation::addLink(int index, const JointSpec& joint, const JointFrames& frames,
                           const PlacedBody& parent, const PlacedBody& child, int parent_link) {
  // Offsets from the loaded poses, so that the articulation starts where the bodies were put.
  const Transform parent_com = toEigen(parent.body->bullet().getCenterOfMassTransform());
  const Transform child_com = toEigen(child.body->bullet().getCenterOfMassTransform());
  const Transform frame_a = parent_com * frames.in_parent;
  const Transform frame_b = child_com * frames.in_child;
  const Eigen::Matrix3d child_from_parent = child_com.linear().transpose() * parent_com.linear();
  const Vec3 parent_com_to_pivot = frames.in_parent.translation();
  const Vec3 pivot_to_child_com =
      child_com.linear().transpose() * (child_com.translation() - frame_a.translation());
  const Vec3 axis = child_from_parent * frames.in_parent.linear() * constraintAxis(joint.type);
  const btQuaternion rotation = toBt(Quat(child_from_parent));

  const btRigidBody& body = child.body->bullet();
  const double mass = child.body->mass();
  const btVector3 inertia = body.getLocalInertia();
  auto& link = links_[static_cast<std::size_t>(index)];
  link.body = child.body;
  link.linear_damping_rate = dampingRate(child.body->spec().surface.linear_damping, step_size_);
  link.angular_damping_rate = dampingRate(child.body->spec().surface.angular_damping, step_size_);
  damped_ = damped_ || link.linear_damping_rate > 0.0 || link.angular_damping_rate > 0.0;
  link.type = joint.type;
  link.coordinate_at_load = coordinateAtLoad(joint, frame_a, frame_b);
  const bool no_collision = joint.ignore_inter_collision;
  switch (joint.type) {
    case JointType::Revolute:
    case JointType::Continuous:
      multibody_->setupRevolute(index, mass, inertia, parent_link, rotation, toBt(axis),
                                toBt(parent_com_to_pivot), toBt(pivot_to_child_com), no_collision);
      break;
    case JointType::Prismatic:
      multibody_->setupPrismatic(index, mass, inertia, parent_link, rotation, toBt(axis),
                                 toBt(parent_com_to_pivot), toBt(pivot_to_child_com), no_collision);
      break;
    default:
      multibody_->setupFixed(index, mass, inertia, parent_link, rotation, toBt(parent_com_to_pivot),
                             toBt(pivot_to_child_com), no_collision);
      return;
  }
  // Bullet normalises hinge limits into [-pi, pi]; the constraint formulation enforces wider
  // ones on commands only, and so does this one.
  const bool bounded = joint.limits && (joint.type == JointType::Prismatic ||
                                        (joint.type == JointType::Revolute &&
                                         joint.limits->low >= -M_PI && joint.limits->high <= M_PI));
  if (bounded) {
    link.limit = std::make_unique<JointLimitConstraint>(
        multibody_.get(), index, joint.limits->low - link.coordinate_at_load,
        joint.limits->high - link.coordinate_at_load);
  }
}

void Articulation::refreshInverseInertia() {
  const int dofs = multibody_->getNumDofs();
  for (int dof = 0; dof < dofs; ++dof) {
    // Column `dof` of M^-1: the joint accelerations a unit generalised force there causes.
    unit_force_[static_cast<std::size_t>(6 + dof)] = 1.0;
    multibody_->calcAccelerationDeltasMultiDof(unit_force_.data(), acceleration_.data(),
                                               scratch_scalars_, scratch_vectors_);
    unit_force_[static_cast<std::size_t>(6 + dof)] = 0.0;
    inverse_inertia_.col(dof) = Eigen::Map<const Eigen::VectorXd>(acceleration_.data() + 6, dofs);
  }
  servo_.setInverseInertia(inverse_inertia_);
  if (servo_.hasTransmission())
    servo_.setLinkWeight(weightTorques(*multibody_, world_.getGravity()));
  steps_since_refresh_ = 0;
}

Eigen::Map<const Eigen::VectorXd> Articulation::jointVelocities() const {
  const btScalar* velocities = multibody_->getVelocityVector() + 6;  // after the base's
  return {velocities, multibody_->getNumDofs()};
}

const Eigen::VectorXd& Articulation::jointPositions() {
  for (int i = 0; i < multibody_->getNumLinks(); ++i) {
    const auto& link = multibody_->getLink(i);
    if (link.m_dofCount == 1) position_(link.m_dofOffset) = multibody_->getJointPos(i);
  }
  return position_;
}

void Articulation::afterFreeMotion() {
  servo_.observeFreeMotion(jointVelocities());
}

void Articulation::beforeStep(double dt) {
  const auto& torque = servo_.torques(jointVelocities(), jointPositions(), dt);
  for (int i = 0; i < multibody_->getNumLinks(); ++i) {
    const auto& link = multibody_->getLink(i);
    if (link.m_dofCount == 1) multibody_->addJointTorque(i, torque(link.m_dofOffset));
  }
  if (damped_ || own_gravity_) applyDampingAndOwnGravity();
}

void Articulation::applyDampingAndOwnGravity() {
  // Bullet scales a damped rigid body's velocities by (1 - d)^h each step. A link is no free
  // body, so the same decay comes as a force and torque on it against its own velocity, which
  // the articulated-body pass shares out over the joints: -c m v and -c I w, in the link's
  // principal frame, with c of dampingRate (exact for a free body, the formulations' difference
  // being O((c h)^2) a step otherwise).
  if (damped_) multibody_->compTreeLinkVelocities(omega_.data(), velocity_.data());
  for (std::size_t i = 0; i < links_.size(); ++i) {
    const Link& link = links_[i];
    const int index = static_cast<int>(i);
    multibody_->addLinkForce(index, link.own_gravity_force);
    if (!damped_) continue;
    const auto& bullet_link = multibody_->getLink(index);
    const btMatrix3x3& basis = link.collider->getWorldTransform().getBasis();
    multibody_->addLinkForce(
        index, basis * (-link.linear_damping_rate * bullet_link.m_mass * velocity_[i + 1]));
    multibody_->addLinkTorque(
        index, basis * (-link.angular_damping_rate * bullet_link.m_inertiaLocal * omega_[i + 1]));
  }
}

std::unique_ptr<JointDynamics> Articulation::jointDynamics(std::size_t index) {
  const int link = link_of_joint_.at(index);
  auto& l = links_[static_cast<std::size_t>(link)];
  return std::make_unique<MultiBodyJoint>(l.type, servo_, world_, *multibody_, link,
                                          l.coordinate_at_load, l.limit.get());
}

Articulation::State Articulation::state() const {
  State s{{}, {}, {}, servo_, inverse_inertia_, steps_since_refresh_};
  for (int i = 0; i < multibody_->getNumLinks(); ++i) s.links.push_back(multibody_->getLink(i));
  const btScalar* velocities = multibody_->getVelocityVector();
  s.velocities.assign(velocities, velocities + 6 + multibody_->getNumDofs());
  for (const auto& link : links_) s.colliders.push_back(motionOf(*link.collider));
  return s;
}

void Articulation::restore(const State& s) {
  for (int i = 0; i < multibody_->getNumLinks(); ++i) {
    multibody_->getLink(i) = s.links[static_cast<std::size_t>(i)];
  }
  multibody_->setBaseOmega({s.velocities[0], s.velocities[1], s.velocities[2]});
  multibody_->setBaseVel({s.velocities[3], s.velocities[4], s.velocities[5]});
  for (int i = 0; i < multibody_->getNumLinks(); ++i) {
    const auto& link = multibody_->getLink(i);
    if (link.m_dofCount > 0) {
      multibody_->setJointVelMultiDof(
          i, &s.velocities[static_cast<std::size_t>(6 + link.m_dofOffset)]);
    }
  }
  for (std::size_t i = 0; i < links_.size(); ++i)
    restoreMotion(*links_[i].collider, s.colliders[i]);
  servo_ = s.servo;
  inverse_inertia_ = s.inverse_inertia;
  steps_since_refresh_ = s.steps_since_refresh;
}

void Articulation::afterStep() {
  // Each link's angular and linear velocity (of its centre of mass) in its own frame.
  multibody_->compTreeLinkVelocities(omega_.data(), velocity_.data());
  for (std::size_t i = 0; i < links_.size(); ++i) {
    btRigidBody& mirror = links_[i].body->bullet();
    const btTransform& pose = links_[i].collider->getWorldTransform();
    mirror.setWorldTransform(pose);  // all a reader uses (no inertia tensor, no interpolation)
    mirror.setAngularVelocity(pose.getBasis() * omega_[i + 1]);
    mirror.setLinearVelocity(pose.getBasis() * velocity_[i + 1]);
  }
  if (++steps_since_refresh_ >= kInertiaRefreshSteps) refreshInverseInertia();
}

}  // namespace ambf_like::detail
