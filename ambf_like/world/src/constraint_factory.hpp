#pragma once
// Builds the Bullet constraint that realises a JointSpec between two rigid bodies.

#include <memory>

#include "ambf_like/dynamics/joint_frames.hpp"
#include "ambf_like/joint_spec.hpp"

class btRigidBody;
class btTypedConstraint;

namespace ambf_like::detail {

/// Hinge, slider, fixed, point-to-point, cone-twist or generic 6-DoF spring constraint, with the
/// spec's limits, springs and ERP/CFM, set up the way AMBF sets it up.
std::unique_ptr<btTypedConstraint> makeConstraint(const JointSpec& joint, btRigidBody& parent,
                                                  btRigidBody& child, const JointFrames& frames);

}  // namespace ambf_like::detail
