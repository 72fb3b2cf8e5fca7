#include "ambf_like/dynamics/joint_frames.hpp"

namespace ambf_like::detail {

Vec3 constraintAxis(JointType type) {
  return (type == JointType::Prismatic || type == JointType::ConeTwist) ? Vec3::UnitX()
                                                                        : Vec3::UnitZ();
}

JointFrames computeJointFrames(const JointSpec& joint, const Transform& parent_com_in_body,
                               double parent_scale, const Transform& child_com_in_body,
                               double child_scale) {
  const Vec3 c = constraintAxis(joint.type);
  const Vec3 axis_a = joint.parent_axis.normalized();
  const Vec3 axis_b = joint.child_axis.normalized();

  const Quat constraint_in_parent = rotationBetween(c, axis_a);
  const Quat child_axis_onto_parent = rotationBetween(axis_b, axis_a);
  const Quat child_offset(Eigen::AngleAxisd(joint.child_offset, axis_a));
  // Child orientation relative to the parent at joint position zero.
  const Quat child_in_parent = child_offset * child_axis_onto_parent;

  Transform frame_a = Transform::Identity();
  frame_a.linear() =
      (constraint_in_parent * Quat(Eigen::AngleAxisd(-joint.joint_offset, c))).toRotationMatrix();
  frame_a.translation() = joint.parent_pivot * parent_scale;

  Transform frame_b = Transform::Identity();
  frame_b.linear() = (child_in_parent.inverse() * constraint_in_parent).toRotationMatrix();
  frame_b.translation() = joint.child_pivot * child_scale;

  return {parent_com_in_body.inverse() * frame_a, child_com_in_body.inverse() * frame_b};
}

}  // namespace ambf_like::detail
