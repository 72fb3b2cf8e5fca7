#pragma once
// Rigid transforms and AMBF's roll-pitch-yaw convention, in Eigen.

#include <Eigen/Geometry>

namespace ambf_like {

using Vec3 = Eigen::Vector3d;
using Quat = Eigen::Quaterniond;
using Transform = Eigen::Isometry3d;

/// Rotation from AMBF's {r, p, y} triple: R = Rz(y) * Ry(p) * Rx(r).
inline Quat quatFromRpy(double roll, double pitch, double yaw) {
  return Quat(Eigen::AngleAxisd(yaw, Vec3::UnitZ()) * Eigen::AngleAxisd(pitch, Vec3::UnitY()) *
              Eigen::AngleAxisd(roll, Vec3::UnitX()));
}

/// The shortest rotation taking unit direction `from` onto unit direction `to` (exact, also for
/// anti-parallel vectors, unlike AMBF's version which snaps angles under 0.1 rad to identity).
inline Quat rotationBetween(const Vec3& from, const Vec3& to) {
  return Quat::FromTwoVectors(from.normalized(), to.normalized());
}

}  // namespace ambf_like
