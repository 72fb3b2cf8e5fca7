#pragma once
// The constraint frames of a joint in its parent's and child's centre-of-mass frames.

#include "ambf_like/joint_spec.hpp"

namespace ambf_like::detail {

/// Constraint frames in each body's COM frame; they coincide in the world at joint position zero.
struct JointFrames {
  Transform in_parent = Transform::Identity();
  Transform in_child = Transform::Identity();
};

/// The body-frame axis Bullet's constraint of this type acts along (z for hinges, x for sliders).
Vec3 constraintAxis(JointType type);

/// AMBF's construction: frame A at the parent pivot with its constraint axis along the parent
/// axis; frame B at the child pivot such that, at zero, the child axis lies on the parent axis
/// and the child is turned by `child offset` about it. `joint offset` shifts the zero reading.
JointFrames computeJointFrames(const JointSpec& joint, const Transform& parent_com_in_body,
                               double parent_scale, const Transform& child_com_in_body,
                               double child_scale);

}  // namespace ambf_like::detail
