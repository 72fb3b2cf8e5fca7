#include "ambf_like/transmission.hpp"

#include <BulletDynamics/Featherstone/btMultiBody.h>

#include <cmath>
#include <stdexcept>

#include "ambf_like/dynamics/joint_space_servo.hpp"
#include "ambf_like/dynamics/multibody_weight.hpp"
#include "ambf_like/dynamics/rotor_response.hpp"
#include "ambf_like/world.hpp"
#include "world_impl.hpp"

namespace ambf_like {

namespace {

/// Throws std::invalid_argument unless there are `motors` finite inertias (> 0) and viscous
/// frictions (>= 0).
void requireRotors(Eigen::Index motors, const Eigen::VectorXd& inertia,
                   const Eigen::VectorXd& viscous) {
  if (inertia.size() != motors || viscous.size() != motors) {
    throw std::invalid_argument("transmission: " + std::to_string(motors) + " motors, " +
                                std::to_string(inertia.size()) + " rotor_inertia, " +
                                std::to_string(viscous.size()) + " viscous");
  }
  for (Eigen::Index m = 0; m < motors; ++m) {
    if (!(inertia(m) > 0.0) || !std::isfinite(inertia(m))) {
      throw std::invalid_argument("transmission: rotor_inertia of motor " + std::to_string(m) +
                                  " must be finite and > 0");
    }
    if (!(viscous(m) >= 0.0) || !std::isfinite(viscous(m))) {
      throw std::invalid_argument("transmission: viscous of motor " + std::to_string(m) +
                                  " must be finite and >= 0");
    }
  }
}

void requireShape(const TransmissionSpec& spec) {
  const auto motors = spec.coupling.rows();
  const auto joints = static_cast<Eigen::Index>(spec.joints.size());
  if (joints == 0 || spec.coupling.cols() != joints || motors == 0) {
    throw std::invalid_argument("transmission: coupling is " + std::to_string(motors) + " x " +
                                std::to_string(spec.coupling.cols()) + " for " +
                                std::to_string(joints) + " joints");
  }
  if (!spec.coupling.allFinite()) throw std::invalid_argument("transmission: coupling not finite");
  requireRotors(motors, spec.rotor_inertia, spec.viscous);
}

}  // namespace

Transmission::Transmission(detail::JointSpaceServo& servo, std::vector<int> dofs,
                           Eigen::MatrixXd coupling)
    : servo_(servo), dofs_(std::move(dofs)), coupling_(std::move(coupling)) {}

void Transmission::drive(const Eigen::VectorXd& torque, const Eigen::VectorXd& coulomb) {
  if (torque.size() != motorCount() || coulomb.size() != motorCount()) {
    throw std::invalid_argument("transmission: " + std::to_string(motorCount()) +
                                " motors, given " + std::to_string(torque.size()) +
                                " torques and " + std::to_string(coulomb.size()) + " frictions");
  }
  for (int m = 0; m < motorCount(); ++m) {
    if (!std::isfinite(torque(m)) || !std::isfinite(coulomb(m)) || coulomb(m) < 0.0) {
      throw std::invalid_argument(
          "transmission: motor " + std::to_string(m) + ": torque " + std::to_string(torque(m)) +
          ", friction " + std::to_string(coulomb(m)) + " (finite, friction >= 0); nothing applied");
    }
  }
  servo_.driveTransmission(torque, coulomb);
}

void Transmission::setRotors(const Eigen::VectorXd& inertia, const Eigen::VectorXd& viscous) {
  requireRotors(motorCount(), inertia, viscous);
  servo_.setRotors(inertia, viscous);
}

Eigen::VectorXd Transmission::linkWeight() const {
  const Eigen::VectorXd& all = servo_.linkWeight();
  Eigen::VectorXd weight(dofs_.size());
  for (std::size_t j = 0; j < dofs_.size(); ++j) {
    weight(static_cast<Eigen::Index>(j)) = all(dofs_[j]);
  }
  return weight;
}

Eigen::MatrixXd Transmission::linkInertia() const {
  const Eigen::MatrixXd& inverse = servo_.inverseInertia();
  Eigen::MatrixXd joints(dofs_.size(), dofs_.size());
  for (std::size_t i = 0; i < dofs_.size(); ++i) {
    for (std::size_t j = 0; j < dofs_.size(); ++j) joints(i, j) = inverse(dofs_[i], dofs_[j]);
  }
  const Eigen::MatrixXd mobility = coupling_ * joints * coupling_.transpose();
  return mobility.llt().solve(Eigen::MatrixXd::Identity(motorCount(), motorCount()));
}

Transmission& World::addTransmission(const TransmissionSpec& spec) {
  requireShape(spec);
  detail::JointSpaceServo* servo = nullptr;
  btMultiBody* multibody = nullptr;
  std::vector<int> dofs;
  for (const auto& name : spec.joints) {
    const auto at = joint(name).dynamics().servoDof();
    if (at.servo == nullptr || (servo != nullptr && at.servo != servo)) {
      throw std::invalid_argument(
          "transmission: joint '" + name +
          "' is not a coordinate of the articulation the others are in (a transmission needs "
          "its joints in one articulation: 'articulation: reduced' in the world file)");
    }
    servo = at.servo;
    multibody = at.multibody;
    dofs.push_back(at.dof);
  }
  if (servo->hasTransmission()) {
    throw std::invalid_argument("transmission: joint '" + spec.joints.front() +
                                "''s articulation already has a transmission");
  }
  const auto all = servo->inverseInertia().rows();
  Eigen::MatrixXd coupling = Eigen::MatrixXd::Zero(spec.coupling.rows(), all);
  for (std::size_t j = 0; j < dofs.size(); ++j) {
    coupling.col(dofs[j]) = spec.coupling.col(static_cast<Eigen::Index>(j));
  }
  const auto motors = spec.coupling.rows();
  const auto dofs_all = Eigen::MatrixXd::Zero(all, all);
  servo->setTransmission({coupling, dofs_all, dofs_all, Eigen::VectorXd::Zero(motors),
                          Eigen::VectorXd::Zero(motors), stepSize()});
  servo->setRotors(spec.rotor_inertia, spec.viscous);
  detail::carryRotors(*multibody, *servo);
  const Vec3& g = settings().gravity;
  servo->setLinkWeight(detail::weightTorques(*multibody, btVector3(g.x(), g.y(), g.z())));
  return *impl_->transmissions.emplace_back(
      std::make_unique<Transmission>(*servo, std::move(dofs), spec.coupling));
}

}  // namespace ambf_like
