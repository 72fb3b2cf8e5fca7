#include "constraint_factory.hpp"

#include <BulletDynamics/ConstraintSolver/btConeTwistConstraint.h>
#include <BulletDynamics/ConstraintSolver/btFixedConstraint.h>
#include <BulletDynamics/ConstraintSolver/btGeneric6DofSpring2Constraint.h>
#include <BulletDynamics/ConstraintSolver/btHingeConstraint.h>
#include <BulletDynamics/ConstraintSolver/btPoint2PointConstraint.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>

#include <cmath>

#include "ambf_like/bullet_conversions.hpp"

namespace ambf_like::detail {

namespace {

std::unique_ptr<btTypedConstraint> makeHinge(const JointSpec& joint, btRigidBody& parent,
                                             btRigidBody& child, const JointFrames& frames) {
  auto hinge = std::make_unique<btHingeConstraint>(parent, child, toBt(frames.in_parent),
                                                   toBt(frames.in_child), true);
  // Bullet normalises hinge limits into [-pi, pi]; wider limits are enforced on commands only.
  const bool representable =
      joint.limits && joint.limits->low >= -M_PI && joint.limits->high <= M_PI;
  if (joint.type == JointType::Revolute && representable) {
    hinge->setLimit(joint.limits->low, joint.limits->high);
  }
  hinge->setParam(BT_CONSTRAINT_ERP, joint.erp);
  hinge->setParam(BT_CONSTRAINT_CFM, joint.cfm);
  return hinge;
}

/// A prismatic joint: a 6-DoF constraint free along x only. AMBF uses btSliderConstraint, but that
/// one comes apart under strong motors (its coordinate and the bodies disagree by centimetres);
/// the 6-DoF constraint holds for any motor impulse.
std::unique_ptr<btTypedConstraint> makePrismatic(const JointSpec& joint, btRigidBody& parent,
                                                 btRigidBody& child, const JointFrames& frames) {
  auto prismatic = std::make_unique<btGeneric6DofSpring2Constraint>(
      parent, child, toBt(frames.in_parent), toBt(frames.in_child));
  for (int i = 0; i < 6; ++i) {
    prismatic->setLimit(i, 0.0, 0.0);
    prismatic->setParam(BT_CONSTRAINT_STOP_ERP, joint.erp, i);
    prismatic->setParam(BT_CONSTRAINT_STOP_CFM, joint.cfm, i);
  }
  if (joint.limits) {
    prismatic->setLimit(0, joint.limits->low, joint.limits->high);
  } else {
    prismatic->setLimit(0, 1.0, -1.0);  // lower > upper: free
  }
  return prismatic;
}

/// Sets axis `i` (0-2 linear, 3-5 angular) of a 6-DoF constraint to [low, high] given in this
/// project's convention. Bullet's angular coordinates are minus the right-hand rotation of the
/// child relative to the parent (AMBF inverts its torsion-spring limits for the same reason).
void setAxisLimit(btGeneric6DofSpring2Constraint& six, int i, double low, double high) {
  if (i < 3) {
    six.setLimit(i, low, high);
  } else {
    six.setLimit(i, -high, -low);
  }
}

void setAxisEquilibrium(btGeneric6DofSpring2Constraint& six, int i, double value) {
  six.setEquilibriumPoint(i, i < 3 ? value : -value);
}

/// A single-axis spring: every axis locked but `axis` (2: linear z, 5: angular z).
std::unique_ptr<btTypedConstraint> makeSpring(const JointSpec& joint, btRigidBody& parent,
                                              btRigidBody& child, const JointFrames& frames) {
  auto spring = std::make_unique<btGeneric6DofSpring2Constraint>(
      parent, child, toBt(frames.in_parent), toBt(frames.in_child));
  for (int i = 0; i < 6; ++i) spring->setLimit(i, 0.0, 0.0);
  const int axis = joint.type == JointType::LinearSpring ? 2 : 5;
  double low = 0.0, high = 0.0;
  if (joint.limits) {
    low = joint.limits->low;
    high = joint.limits->high;
    setAxisLimit(*spring, axis, low, high);
  } else {
    spring->setLimit(axis, 1.0, -1.0);  // lower > upper: free
  }
  // AMBF's default stiffness (its formula, operator precedence included).
  const double mass_a = parent.getInvMass() > 0.0 ? 1.0 / parent.getInvMass() : 0.0;
  const double mass_b = child.getInvMass() > 0.0 ? 1.0 / child.getInvMass() : 0.0;
  spring->enableSpring(axis, true);
  spring->setStiffness(axis, joint.stiffness.value_or(10.0 * mass_a + mass_b));
  spring->setDamping(axis, joint.damping);
  setAxisEquilibrium(*spring, axis, joint.equilibrium_point.value_or(low + (high - low) / 2.0));
  spring->setParam(BT_CONSTRAINT_STOP_ERP, joint.erp, axis);
  spring->setParam(BT_CONSTRAINT_STOP_CFM, joint.cfm, axis);
  return spring;
}

std::unique_ptr<btTypedConstraint> makeSixDof(const JointSpec& joint, btRigidBody& parent,
                                              btRigidBody& child, const JointFrames& frames) {
  auto six = std::make_unique<btGeneric6DofSpring2Constraint>(parent, child, toBt(frames.in_parent),
                                                              toBt(frames.in_child));
  const auto& d = joint.six_dof;
  for (int i = 0; i < 6; ++i) {
    const auto k = static_cast<std::size_t>(i);
    setAxisLimit(*six, i, d.low[k], d.high[k]);
    if (joint.type != JointType::SixDofSpring) continue;
    six->enableSpring(i, true);
    six->setStiffness(i, d.stiffness[k]);
    six->setDamping(i, d.damping[k]);
    setAxisEquilibrium(*six, i, d.equilibrium[k]);
  }
  return six;
}

}  // namespace

std::unique_ptr<btTypedConstraint> makeConstraint(const JointSpec& joint, btRigidBody& parent,
                                                  btRigidBody& child, const JointFrames& frames) {
  switch (joint.type) {
    case JointType::Revolute:
    case JointType::Continuous:
      return makeHinge(joint, parent, child, frames);
    case JointType::Prismatic:
      return makePrismatic(joint, parent, child, frames);
    case JointType::Fixed:
      return std::make_unique<btFixedConstraint>(parent, child, toBt(frames.in_parent),
                                                 toBt(frames.in_child));
    case JointType::P2P: {
      auto p2p = std::make_unique<btPoint2PointConstraint>(
          parent, child, toBt(Vec3(frames.in_parent.translation())),
          toBt(Vec3(frames.in_child.translation())));
      p2p->setParam(BT_CONSTRAINT_ERP, joint.erp);
      p2p->setParam(BT_CONSTRAINT_CFM, joint.cfm);
      return p2p;
    }
    case JointType::LinearSpring:
    case JointType::TorsionSpring:
      return makeSpring(joint, parent, child, frames);
    case JointType::ConeTwist: {
      auto cone = std::make_unique<btConeTwistConstraint>(parent, child, toBt(frames.in_parent),
                                                          toBt(frames.in_child));
      const auto& l = joint.cone_twist_limits;
      cone->setLimit(l.y(), l.z(), l.x());
      return cone;
    }
    case JointType::SixDof:
    case JointType::SixDofSpring:
      return makeSixDof(joint, parent, child, frames);
  }
  return nullptr;
}

}  // namespace ambf_like::detail
