#pragma once
// One arm's modified-DH chain and the map from joint values to DH variables.

#include <Eigen/Geometry>
#include <array>

namespace raven {

/// The Raven-II arm as a modified (Craig) DH chain, link transform Rx(alpha) Tx(a) Rz(theta)
/// Tz(d), rows 0..5:
///   0: (alpha0, 0, theta1, 0)        shoulder
///   1: (alpha1, 0, theta2, 0)        elbow
///   2: (alpha2, 0, insertion_theta, q3)   insertion (prismatic)
///   3: (0,      0, theta4, d4)       tool roll
///   4: (alpha4, 0, theta5, 0)        wrist
///   5: (alpha5, tool_length, theta6, 0)   grasper (theta6 from the jaws)
/// Rows 0-2 form a spherical remote-centre mechanism: the first three axes meet at the origin.
/// A convention also says how joints become DH values: theta_i = wrap(q_i + theta_offset_i)
/// and theta6 = wrap(grasp_scale * (jaw1 - jaw2)).
struct ArmConvention {
  Eigen::Isometry3d base = Eigen::Isometry3d::Identity();  ///< reporting frame -> row 0
  std::array<double, 6> alpha{};                           ///< rad
  double tool_length = 0.0;                                ///< a of row 5 (Lw), m
  double d4 = 0.0;                                         ///< d of row 3, m
  double insertion_theta = 0.0;                            ///< fixed theta of row 2, rad
  /// Added to shoulder, elbow, (unused: insertion), roll, wrist before wrapping.
  std::array<double, 5> theta_offset{};
  double grasp_scale = 1.0;  ///< theta6 = grasp_scale * (jaw1 - jaw2)
};

}  // namespace raven
