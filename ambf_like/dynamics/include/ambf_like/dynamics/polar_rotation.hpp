#pragma once
// The rotation of a deformation gradient's polar decomposition, followed from step to step.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "ambf_like/dynamics/lane_matrix.hpp"

namespace ambf_like::detail {

/// A rotation followed from step to step: as a unit quaternion, and as the matrix it makes.
struct Rotation {
  Eigen::Quaterniond quaternion = Eigen::Quaterniond::Identity();
  Eigen::Matrix3d matrix = Eigen::Matrix3d::Identity();
};

/// A Rotation of T (double, or Lanes: four rotations side by side).
template <typename T>
struct FollowedRotation {
  T w = T{} + 1.0, x{}, y{}, z{};  ///< the unit quaternion
  Matrix9<T> matrix{T{} + 1.0, T{}, T{}, T{}, T{} + 1.0, T{}, T{}, T{}, T{} + 1.0};
};

/// Updates `rotation` towards the rotation of `f`'s polar decomposition (at most 4 iterations,
/// none once within 1e-4 rad); returns R^T f for the rotation it ends with. Lane by lane for
/// Lanes: a lane already within the tolerance is left as it is.
template <typename T>
Matrix9<T> followRotation(const Matrix9<T>& f, FollowedRotation<T>& rotation);

/// The same for one Eigen matrix and Rotation.
Eigen::Matrix3d followRotation(const Eigen::Matrix3d& f, Rotation& rotation);

}  // namespace ambf_like::detail
