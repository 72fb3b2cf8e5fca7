#include "articulation.hpp"

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyJointLimitConstraint.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

#include <algorithm>
#include <cmath>
#include <deque>

#include "ambf_like/bullet_conversions.hpp"
#include "bullet_world.hpp"
#include "multibody_joint.hpp"

namespace ambf_like::detail {

namespace {

/// Steps between refreshes of the joint-space inverse inertia (one articulated-body pass per
/// joint). In 10 ms a joint at 3 rad/s (the Raven's speed limit) turns 0.03 rad: it barely moves.
constexpr int kInertiaRefreshSteps = 10;

int dofCount(const ModelSpec& model) {
  return static_cast<int>(std::count_if(model.joints.begin(), model.joints.end(),
                                        [](const JointSpec& j) { return j.isSingleAxis(); }));
}

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

std::string rootName(const ModelSpec& model) {
  for (const auto& body : model.bodies) {
    if (body.mass == 0.0) return body.name;
  }
  return {};
}

/// The model's joints, parents first, breadth first from its static root; those of bodies that
/// do not hang from the root are missing.
std::vector<std::size_t> jointsFromRoot(const ModelSpec& model) {
  std::vector<std::size_t> order;
  std::deque<std::string> frontier{rootName(model)};
  while (!frontier.empty() && order.size() < model.joints.size()) {
    const std::string parent = frontier.front();
    frontier.pop_front();
    for (std::size_t j = 0; j < model.joints.size(); ++j) {
      if (model.joints[j].parent != parent) continue;
      order.push_back(j);
      frontier.push_back(model.joints[j].child);
    }
  }
  return order;
}

}  // namespace

std::optional<std::string> whyNotArticulable(const ModelSpec& model) {
  if (model.joints.empty()) return "it has no joints";
  if (model.gravity) return "it has a gravity of its own";
  std::map<std::string, int> parents_of;
  for (const auto& joint : model.joints) {
    if (!isArticulableJoint(joint.type))
      return "joint '" + joint.name + "' is not revolute, continuous, prismatic or fixed";
    ++parents_of[joint.child];
  }
  int roots = 0;
  for (const auto& body : model.bodies) {
    const int parents = parents_of.count(body.name) ? parents_of.at(body.name) : 0;
    if (body.mass == 0.0) {
      if (parents > 0) return "static body '" + body.name + "' hangs from a joint";
      ++roots;
      continue;
    }
    if (parents != 1) return "body '" + body.name + "' is not the child of exactly one joint";
    if (body.gravity) return "body '" + body.name + "' has a gravity of its own";
    if (body.surface.linear_damping != 0.0 || body.surface.angular_damping != 0.0)
      return "body '" + body.name + "' is damped";
  }
  if (roots != 1) return "it has " + std::to_string(roots) + " static bodies, not one root";
  if (jointsFromRoot(model).size() != model.joints.size())
    return "its joints do not connect every body to its static root";
  return std::nullopt;
}

struct Articulation::Link {
  RigidBody* body = nullptr;
  std::unique_ptr<btMultiBodyLinkCollider> collider;
  std::unique_ptr<btMultiBodyJointLimitConstraint> limit;
  JointType type = JointType::Fixed;
  double coordinate_at_load = 0.0;
};

Articulation::Articulation(const ModelSpec& model, const std::map<std::string, PlacedBody>& bodies,
                           btMultiBodyDynamicsWorld& world)
    : world_(world), link_of_joint_(model.joints.size(), -1), servo_(dofCount(model)) {
  const auto order = jointsFromRoot(model);
  std::map<std::string, int> link_of_body{{rootName(model), -1}};
  for (std::size_t link = 0; link < order.size(); ++link) {
    link_of_joint_[order[link]] = static_cast<int>(link);
    link_of_body[model.joints[order[link]].child] = static_cast<int>(link);
  }
  const RigidBody& root = *bodies.at(rootName(model)).body;

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
  }
  multibody_->finalizeMultiDof();
  omega_.resize(links_.size() + 1);  // the base's first
  velocity_.resize(links_.size() + 1);
  const auto dofs = static_cast<std::size_t>(multibody_->getNumDofs());
  unit_force_.assign(6 + dofs, 0.0);  // the base's six first
  acceleration_.assign(6 + dofs, 0.0);
  inverse_inertia_.resize(multibody_->getNumDofs(), multibody_->getNumDofs());
  multibody_->setLinearDamping(0.0);
  multibody_->setAngularDamping(0.0);
  multibody_->setHasSelfCollision(!model.ignore_inter_collision);
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

void Articulation::engageLimit(btMultiBodyJointLimitConstraint& limit, bool engaged) {
  if (engaged) {
    world_.addMultiBodyConstraint(&limit);
  } else {
    world_.removeMultiBodyConstraint(&limit);
  }
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
    link.limit = std::make_unique<btMultiBodyJointLimitConstraint>(
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
  steps_since_refresh_ = 0;
}

Eigen::Map<const Eigen::VectorXd> Articulation::jointVelocities() const {
  const btScalar* velocities = multibody_->getVelocityVector() + 6;  // after the base's
  return {velocities, multibody_->getNumDofs()};
}

void Articulation::afterFreeMotion() {
  servo_.observeFreeMotion(jointVelocities());
}

void Articulation::beforeStep(double dt) {
  const auto& torque = servo_.torques(jointVelocities(), dt);
  for (int i = 0; i < multibody_->getNumLinks(); ++i) {
    const auto& link = multibody_->getLink(i);
    if (link.m_dofCount == 1) multibody_->addJointTorque(i, torque(link.m_dofOffset));
  }
}

std::unique_ptr<JointDynamics> Articulation::jointDynamics(std::size_t index) {
  const int link = link_of_joint_.at(index);
  auto& l = links_[static_cast<std::size_t>(link)];
  return std::make_unique<MultiBodyJoint>(l.type, *this, *multibody_, link, l.coordinate_at_load,
                                          l.limit.get());
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
