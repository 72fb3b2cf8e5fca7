#pragma once
// AMBF's constraint actuator: on command it attaches a point of a body to its parent where that
// point is now (a point-to-point constraint under an impulse clamp and tau), or anchors nodes of
// a soft body to its parent where they are (Bullet soft-body anchors, as AMBF takes a soft body
// by a sensed face), and lets go on release. SRC grasps its needle this way when a proximity
// sensor sees it.

#include <memory>
#include <string>
#include <vector>

#include "ambf_like/rigid_body.hpp"
#include "ambf_like/sensor_spec.hpp"
#include "ambf_like/soft_body.hpp"

class btDiscreteDynamicsWorld;
class btPoint2PointConstraint;

namespace ambf_like {

class ConstraintActuator {
 public:
  /// Throws std::invalid_argument when the parent is an articulation link (no Bullet rigid
  /// body to attach to: give its model `articulation: maximal`).
  ConstraintActuator(ActuatorSpec spec, std::string qualified_name, RigidBody& parent,
                     bool parent_in_world, btDiscreteDynamicsWorld& world);
  ~ConstraintActuator();
  ConstraintActuator(const ConstraintActuator&) = delete;
  ConstraintActuator& operator=(const ConstraintActuator&) = delete;

  const std::string& name() const { return spec_.name; }
  const std::string& qualifiedName() const { return qualified_name_; }
  const ActuatorSpec& spec() const { return spec_; }

  /// Attaches the point `offset` (body frame; default its origin) of `body`, a dynamic rigid
  /// body, to the parent where the point is now, releasing any other body first.
  void actuate(RigidBody& body, const Vec3& offset = Vec3::Zero());
  /// Anchors the nodes `nodes` of `body` to the parent where they are now (nodes it already
  /// holds are kept, so several sensed faces add up), releasing any rigid body first. Throws
  /// std::invalid_argument for a node index out of range.
  void actuate(SoftBody& body, const std::vector<int>& nodes);
  void release();
  bool actuated() const { return held_ != nullptr || held_soft_ != nullptr; }
  /// The held body's qualified name, or empty.
  std::string heldBody() const;
  /// The actuator's location in the world frame, from the parent's pose now.
  Vec3 pointInWorld() const;

  /// What it holds, and where (World::saveState): a world's state is restored only onto the
  /// same holds.
  struct Hold {
    const RigidBody* rigid = nullptr;
    const SoftBody* soft = nullptr;
    std::vector<int> nodes;
    Vec3 pivot_in_parent = Vec3::Zero(), pivot_in_body = Vec3::Zero();
    bool sameAs(const Hold& other) const;
  };
  Hold hold() const;

 private:
  ActuatorSpec spec_;
  std::string qualified_name_;
  RigidBody& parent_;
  btDiscreteDynamicsWorld& world_;
  std::unique_ptr<btPoint2PointConstraint> constraint_;
  RigidBody* held_ = nullptr;
  SoftBody* held_soft_ = nullptr;
  std::vector<int> anchored_;  ///< nodes of held_soft_
};

}  // namespace ambf_like
