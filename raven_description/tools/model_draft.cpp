#include "model_draft.hpp"

#include <cmath>
#include <stdexcept>

namespace raven::model {

using Eigen::Isometry3d;
using Eigen::Matrix3d;
using Eigen::Quaterniond;
using Eigen::Vector3d;

const BodyDraft& ModelDraft::body(const std::string& name) const {
  for (const auto& b : bodies) {
    if (b.name == name) return b;
  }
  throw std::out_of_range("no drafted body " + name);
}

// AMBF's frames put the child, at joint position zero, at Rot(parent axis, offset) * Q relative
// to the parent, Q the shortest rotation taking the child axis onto the parent axis; a hinge
// then reads the rotation phi about the axis beyond that, minus the offset (see ambf_like's
// joint_frames). So the offset is phi minus the position the joint should read now.
JointDraft connect(const std::string& name, const BodyDraft& parent, const BodyDraft& child,
                   const Vector3d& axis_in_child, const Vector3d& pivot_in_child,
                   double position_now, bool prismatic) {
  const Isometry3d relative = parent.pose.inverse() * child.pose;
  JointDraft j;
  j.name = name;
  j.parent = parent.name;
  j.child = child.name;
  j.prismatic = prismatic;
  j.child_axis = axis_in_child.normalized();
  j.child_pivot = pivot_in_child;
  j.parent_axis = relative.linear() * j.child_axis;
  // A slider reads the pivots' separation along the axis: put the parent's where it reads zero.
  j.parent_pivot = relative * (prismatic ? Vector3d(pivot_in_child - position_now * j.child_axis)
                                         : pivot_in_child);

  const Matrix3d q = Quaterniond::FromTwoVectors(j.child_axis, j.parent_axis).toRotationMatrix();
  const Matrix3d about_axis = relative.linear() * q.transpose();  // = Rot(parent axis, phi)
  const Vector3d& a = j.parent_axis;
  const Vector3d v = a.unitOrthogonal();
  const double phi = std::atan2(a.dot(v.cross(about_axis * v)), v.dot(about_axis * v));
  j.offset = prismatic ? phi : phi - position_now;
  return j;
}

Vector3d centreOfMass(const BodyDraft& body) {
  if (body.centre_of_mass) return *body.centre_of_mass;
  if (!body.hull.empty()) {
    Eigen::AlignedBox3d box;
    for (const auto& v : body.hull) box.extend(v);
    return box.center();
  }
  Vector3d sum = Vector3d::Zero();
  double volume = 0.0;
  for (const auto& p : body.primitives) {
    sum += p.volume() * p.pose.translation();
    volume += p.volume();
  }
  return volume > 0.0 ? Vector3d(sum / volume) : Vector3d::Zero();
}

}  // namespace raven::model
