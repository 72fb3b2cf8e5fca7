#include "twin/gravity_compensation.hpp"

#include <Eigen/Geometry>

#include "raven/design/firmware_links.hpp"
#include "raven/platform_profile.hpp"

namespace twin {

namespace {

/// The robot's own firmware chain (profiles/physical.yaml's firmware_kinematics: the reference's
/// section A), in each arm's base frame: the frames its gravity law works in.
const raven::ArmConvention& firmwareChain(Arm arm) {
  static const raven::PerArm<raven::ArmConvention> chains =
      *raven::builtinProfile("physical").firmware_kinematics;
  return chains[raven::slot(arm)];
}

/// One modified-DH link transform (raven2-kinematics.md: Rx(alpha) Tx(a) Rz(theta) Tz(d)), a = 0
/// on the first three rows.
Eigen::Isometry3d link(double alpha, double theta, double d) {
  return Eigen::Isometry3d(Eigen::AngleAxisd(alpha, Eigen::Vector3d::UnitX())) *
         Eigen::Isometry3d(Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitZ())) *
         Eigen::Translation3d(0.0, 0.0, d);
}

}  // namespace

ArmJoints gravityCompensation(Arm arm, const ArmJoints& q, const DriveTrain& drive) {
  // The first three rows of the robot's own DH with its joint offsets.
  const raven::ArmConvention& chain = firmwareChain(arm);
  const Eigen::Isometry3d t01 =
      link(chain.alpha[0], q(raven::kShoulder) + chain.theta_offset[raven::kShoulder], 0.0);
  const Eigen::Isometry3d t12 =
      link(chain.alpha[1], q(raven::kElbow) + chain.theta_offset[raven::kElbow], 0.0);
  const Eigen::Isometry3d t23 = link(chain.alpha[2], chain.insertion_theta, q(raven::kInsertion));
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
