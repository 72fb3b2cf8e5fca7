#include "twin/gravity_compensation.hpp"

#include <Eigen/Geometry>
#include <cmath>

#include "raven/design/firmware_links.hpp"

namespace twin {

namespace {

constexpr double kDeg = M_PI / 180.0;

/// One modified-DH link transform (raven2-kinematics.md: Rx(alpha) Tx(a) Rz(theta) Tz(d)).
Eigen::Isometry3d link(double alpha, double theta, double d) {
  return Eigen::Isometry3d(Eigen::AngleAxisd(alpha, Eigen::Vector3d::UnitX())) *
         Eigen::Isometry3d(Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitZ())) *
         Eigen::Translation3d(0.0, 0.0, d);
}

}  // namespace

ArmJoints gravityCompensation(Arm arm, const ArmJoints& q, const DriveTrain& drive) {
  const bool gold = arm == Arm::Left;
  // The first three rows of the robot's own DH (raven2-kinematics.md §A) with its joint offsets.
  const Eigen::Isometry3d t01 =
      link(gold ? 0.0 : M_PI, q(raven::kShoulder) + (gold ? 205.0 : 25.0) * kDeg, 0.0);
  const Eigen::Isometry3d t12 = link(75.0 * kDeg, q(raven::kElbow) + (gold ? M_PI : 0.0), 0.0);
  const Eigen::Isometry3d t23 = link(gold ? M_PI - 52.0 * kDeg : 52.0 * kDeg,
                                     gold ? M_PI / 2 : -M_PI / 2, q(raven::kInsertion));
  const auto links = raven::design::FirmwareLinks::of(arm);
  const auto& [m1, m2, m3] = links.mass;
  const Eigen::Vector3d& com1 = links.centre[0];
  const Eigen::Vector3d& com2 = links.centre[1];
  // Gravity in each arm's frame 0 is -x (the firmware's grav_dir), expressed in frames 1-3.
  const Eigen::Vector3d g0(-9.8, 0.0, 0.0);
  const Eigen::Vector3d g1 = t01.linear().transpose() * g0;
  const Eigen::Vector3d g2 = t12.linear().transpose() * g1;
  const Eigen::Vector3d g3 = t23.linear().transpose() * g2;
  const Eigen::Vector3d link2_com_in1 = t12 * com2;
  const Eigen::Vector3d link3_in1 = (t12 * t23).translation();
  const Eigen::Vector3d link3_in2 = t23.translation();
  const Eigen::Vector3d shoulder =
      com1.cross(m1 * g1) + link2_com_in1.cross(m2 * g1) + link3_in1.cross(m3 * g1);
  const Eigen::Vector3d elbow = com2.cross(m2 * g2) + link3_in2.cross(m3 * g2);
  const Eigen::Vector3d insertion = m3 * g3;
  ArmJoints tau = ArmJoints::Zero();
  // Each joint's load is minus its z component, converted diagonally to the gearbox output.
  tau(raven::kShoulder) = -shoulder.z();
  tau(raven::kElbow) = -elbow.z();
  tau(raven::kInsertion) = -insertion.z();
  for (int i = 0; i < 3; ++i) tau(i) *= drive.gearbox(i) / drive.transmission(i);
  return tau;
}

}  // namespace twin
