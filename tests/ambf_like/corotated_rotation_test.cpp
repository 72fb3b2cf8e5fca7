// A tetrahedron's rotation follows its deformation gradient's polar rotation: quickly for a
// stretched, turned element, and to a proper rotation for a crushed one.

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "ambf_like/dynamics/corotated_tets.hpp"

namespace {

using ambf_like::detail::followRotation;
using ambf_like::detail::Rotation;

/// The angle (rad) between two rotations.
double angleBetween(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  return Eigen::AngleAxisd(a.transpose() * b).angle();
}

TEST(CorotatedRotation, AStretchedTurnedElementIsFollowedToItsPolarRotationInOneCall) {
  // F = R S: a 0.3 rad turn of a stretch that differs by 30 % between axes, with shear.
  const Eigen::Matrix3d turned =
      Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  Eigen::Matrix3d stretch;
  stretch << 1.2, 0.05, 0.0, 0.05, 0.9, 0.02, 0.0, 0.02, 1.05;
  const Eigen::Matrix3d f = turned * stretch;
  Rotation rotation;  // the element's last rotation: none
  const Eigen::Matrix3d unrotated = followRotation(f, rotation);
  // Newton's turn converges within the 4 passes of one call (the partial turn t / tr U leaves a
  // third of 0.3 rad after each: 4e-3 rad after 4).
  EXPECT_LT(angleBetween(rotation.matrix, turned), 2e-4);
  EXPECT_TRUE(rotation.matrix.isApprox(rotation.quaternion.toRotationMatrix(), 1e-12));
  EXPECT_TRUE(unrotated.isApprox(rotation.matrix.transpose() * f, 1e-12));
  EXPECT_LT((unrotated - unrotated.transpose()).norm(), 1e-3);  // R^T F is the stretch
}

TEST(CorotatedRotation, ACrushedElementStillGetsAProperRotation) {
  // Inverted through its third axis: tr S I - S is not positive definite, and the partial turn
  // takes over.
  const Eigen::Matrix3d turned =
      Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Matrix3d f = turned * Eigen::Vector3d(1.0, 0.2, -0.5).asDiagonal();
  Rotation rotation;
  followRotation(f, rotation);
  EXPECT_TRUE(rotation.matrix.allFinite());
  EXPECT_NEAR(rotation.matrix.determinant(), 1.0, 1e-12);
  EXPECT_TRUE((rotation.matrix.transpose() * rotation.matrix).isIdentity(1e-12));
}

TEST(CorotatedRotation, AnElementAlreadyFollowedIsLeftAsItIs) {
  const Eigen::Matrix3d turned =
      Eigen::AngleAxisd(1.0, Eigen::Vector3d(0, 1, 1).normalized()).toRotationMatrix();
  Rotation rotation;
  rotation.quaternion = Eigen::Quaterniond(turned);
  rotation.matrix = turned;
  const Eigen::Matrix3d f = turned * Eigen::Vector3d(1.1, 0.95, 1.0).asDiagonal();
  followRotation(f, rotation);
  EXPECT_EQ(rotation.matrix, turned);
}

}  // namespace
