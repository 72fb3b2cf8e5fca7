#include "calibration/mechanics_information.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>

#include "calibration/setpoint_replay.hpp"
#include "twin/motor_controller.hpp"

namespace calibration {

namespace {

using analysis::ActuatorSignal;

constexpr double kDegreesPerRadian = 180.0 / M_PI;

/// The finite-difference step for value `v` at `x`: relative where the value is positive by
/// nature, absolute where it may be 0 or of either sign.
double differenceStep(int v, double x) {
  using M = twin::MotorMechanics;
  switch (v) {
    case 0:  // inertia
      return 0.05 * x;
    case 1:  // coulomb (N m)
      return std::max(0.05 * x, 1e-3);
    case 2:  // load_friction (a fraction of the load)
      return 0.02;
    case 3:  // viscous (N m s)
      return std::max(0.05 * x, 1e-5);
    case M::kOffset:  // N m
      return 1e-3;
    case M::kFace:  // rad
      return 1e-3;
    case M::kFaceCompliance:  // rad per N m
      return std::max(0.05 * x, 0.01);
    case M::kCableFriction:  // N m
      return std::max(0.05 * x, 1e-3);
    case M::kCableTravel:  // motor rad
      return std::max(0.05 * x, 0.01);
    default:  // gravity_error (a fraction of the weight)
      return 0.02;
  }
}

}  // namespace

bool motorHasValue(int joint, int v) {
  if (v == twin::MotorMechanics::kFace || v == twin::MotorMechanics::kFaceCompliance) {
    return joint >= raven::kJaw1;
  }
  // The arm's long cables over its pulleys: the tool's show no give of their own (a fit with
  // one per tool motor put each at the shortest travel it allowed, a rigid cable).
  if (v == twin::MotorMechanics::kGravityError || v == twin::MotorMechanics::kCableFriction ||
      v == twin::MotorMechanics::kCableTravel) {
    return joint <= raven::kInsertion;
  }
  return true;
}

std::array<raven::ArmJoints, 3> quantisationNoise(raven::Arm arm) {
  const twin::DriveTrain drive = twin::DriveTrain::raven2();
  const double count = 1.0 / drive.countsPerMotorRadian();
  const double position = count / std::sqrt(12.0);
  const double velocity = position * std::sqrt(2.0) / 0.001;
  const twin::MotorGains gains = twin::MotorGains::raven2(arm);
  const raven::ArmJoints torque =
      ((gains.kp * position).array().square() + (gains.kd * velocity).array().square()).sqrt();
  return {raven::ArmJoints::Constant(position * kDegreesPerRadian),
          raven::ArmJoints::Constant(velocity * kDegreesPerRadian), torque};
}

MechanicsInformation MechanicsInformation::none() {
  MechanicsInformation info;
  for (auto& arm : info.blocks) arm.fill(InformationBlock::Zero());
  return info;
}

MechanicsInformation MechanicsInformation::fromUncertainty(const twin::ArmsMechanics& sd) {
  MechanicsInformation info = none();
  for (std::size_t a = 0; a < 2; ++a) {
    const twin::MotorMechanics& m = sd[a];
    for (int j = 0; j < raven::kJointCount; ++j) {
      for (int v = 0; v < kMechanicsValues; ++v) {
        const double s = m.field(static_cast<std::size_t>(v))(j);
        if (s > 0.0) info.blocks[a][static_cast<std::size_t>(j)](v, v) = 1.0 / (s * s);
      }
    }
  }
  return info;
}

MechanicsInformation& MechanicsInformation::operator+=(const MechanicsInformation& o) {
  for (std::size_t a = 0; a < 2; ++a) {
    for (std::size_t j = 0; j < blocks[a].size(); ++j) blocks[a][j] += o.blocks[a][j];
  }
  return *this;
}

twin::ArmsMechanics MechanicsInformation::standardDeviations() const {
  twin::ArmsMechanics sd;
  for (std::size_t a = 0; a < 2; ++a) {
    for (std::size_t k = 0; k < twin::MotorMechanics::kNames.size(); ++k) sd[a].field(k).setZero();
    for (int j = 0; j < raven::kJointCount; ++j) {
      const InformationBlock& b = blocks[a][static_cast<std::size_t>(j)];
      // Only the values with information: the rest stay 0 (not fitted, nothing known).
      std::vector<int> used;
      for (int v = 0; v < kMechanicsValues; ++v) {
        if (b(v, v) > 0.0) used.push_back(v);
      }
      if (used.empty()) continue;
      const Eigen::MatrixXd sub = b(used, used);
      const Eigen::MatrixXd covariance = sub.completeOrthogonalDecomposition().pseudoInverse();
      for (std::size_t r = 0; r < used.size(); ++r) {
        sd[a].field(static_cast<std::size_t>(used[r]))(j) = std::sqrt(
            std::max(0.0, covariance(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(r))));
      }
    }
  }
  return sd;
}

double MechanicsInformation::logDet(const twin::ArmsMechanics& fitted) const {
  double sum = 0.0;
  for (std::size_t a = 0; a < 2; ++a) {
    const twin::MotorMechanics& m = fitted[a];
    for (int j = 0; j < raven::kJointCount; ++j) {
      std::vector<int> used;
      for (int v = 0; v < kMechanicsValues; ++v) {
        if (m.field(static_cast<std::size_t>(v))(j) != 0.0) used.push_back(v);
      }
      if (used.empty()) continue;
      const Eigen::MatrixXd sub = blocks[a][static_cast<std::size_t>(j)](used, used);
      const Eigen::LDLT<Eigen::MatrixXd> ldlt(sub);
      for (Eigen::Index k = 0; k < sub.rows(); ++k)
        sum += std::log(std::max(ldlt.vectorD()(k), 1e-300));
    }
  }
  return sum;
}

MechanicsInformation informationOf(const twin::ArmsMechanics& mechanics,
                                   const analysis::ActuatorTrace& recording) {
  constexpr std::array<ActuatorSignal, 3> kSignals{
      ActuatorSignal::MotorPosition, ActuatorSignal::MotorVelocity, ActuatorSignal::Torque};
  const raven::PerArm<std::array<raven::ArmJoints, 3>> sigma{quantisationNoise(raven::Arm::Left),
                                                             quantisationNoise(raven::Arm::Right)};
  const auto base = replaySetpoints(recording, mechanics);
  // Every motor's value v moved at once: the motors are independent, so each motor's signals
  // answer to its own value only.
  std::array<analysis::ActuatorTrace, kMechanicsValues> moved;
  std::array<twin::ArmsMechanics, kMechanicsValues> step;
  for (int v = 0; v < kMechanicsValues; ++v) {
    twin::ArmsMechanics m = mechanics;
    twin::ArmsMechanics h;
    for (std::size_t a = 0; a < 2; ++a) {
      h[a] = m[a];
      for (int j = 0; j < raven::kJointCount; ++j) {
        double& x = m[a].field(static_cast<std::size_t>(v))(j);
        const double d = differenceStep(v, x);
        h[a].field(static_cast<std::size_t>(v))(j) = d;
        if (motorHasValue(j, v)) x += d;  // a value the motor has not stays as it is
      }
    }
    moved[static_cast<std::size_t>(v)] = replaySetpoints(recording, m);
    step[static_cast<std::size_t>(v)] = h;
  }
  MechanicsInformation info = MechanicsInformation::none();
  for (std::size_t a = 0; a < 2; ++a) {
    for (std::size_t s = 0; s < kSignals.size(); ++s) {
      for (std::size_t r = 0; r < base.rows(); ++r) {
        // Per value, every joint's sensitivity in units of the noise.
        const raven::ArmJoints y0 = analysis::logged(base.arms[a][r], kSignals[s]);
        std::array<raven::ArmJoints, kMechanicsValues> dy;
        for (std::size_t v = 0; v < dy.size(); ++v) {
          dy[v] = (analysis::logged(moved[v].arms[a][r], kSignals[s]) - y0)
                      .cwiseQuotient(step[v][a].field(v))
                      .cwiseQuotient(sigma[a][s]);
        }
        for (int j = 0; j < raven::kJointCount; ++j) {
          Eigen::Matrix<double, kMechanicsValues, 1> g =
              Eigen::Matrix<double, kMechanicsValues, 1>::Zero();
          for (int v = 0; v < kMechanicsValues; ++v) {
            if (motorHasValue(j, v)) g(v) = dy[static_cast<std::size_t>(v)](j);
          }
          info.blocks[a][static_cast<std::size_t>(j)] += g * g.transpose();
        }
      }
    }
  }
  return info;
}

}  // namespace calibration
