#pragma once
// Conversions between Eigen (the API's types) and Bullet (the engine's types).

#include <LinearMath/btTransform.h>

#include "ambf_like/transform.hpp"

namespace ambf_like {

inline btVector3 toBt(const Vec3& v) {
  return btVector3(v.x(), v.y(), v.z());
}
inline Vec3 toEigen(const btVector3& v) {
  return Vec3(v.x(), v.y(), v.z());
}

inline btQuaternion toBt(const Quat& q) {
  return btQuaternion(q.x(), q.y(), q.z(), q.w());
}
inline Quat toEigen(const btQuaternion& q) {
  return Quat(q.w(), q.x(), q.y(), q.z());
}

inline Eigen::Matrix3d toEigen(const btMatrix3x3& m) {
  Eigen::Matrix3d out;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) out(r, c) = m[r][c];
  }
  return out;
}

inline btTransform toBt(const Transform& t) {
  return btTransform(toBt(Quat(t.rotation()).normalized()), toBt(Vec3(t.translation())));
}

inline Transform toEigen(const btTransform& t) {
  Transform out = Transform::Identity();
  out.linear() = toEigen(t.getRotation()).toRotationMatrix();
  out.translation() = toEigen(t.getOrigin());
  return out;
}

}  // namespace ambf_like
