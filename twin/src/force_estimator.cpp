#include "twin/force_estimator.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

#include "twin/gravity_compensation.hpp"

namespace twin {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// The firmware's velocity is one encoder count per 1 ms cycle at its finest (mvel's quantum).
constexpr double kCycle = 0.001;

bool finite(const ArmJoints& v) {
  return v.allFinite();
}

ForceEstimate unknown() {
  ForceEstimate e;
  e.tip.setConstant(kNaN);
  e.tip_sd.setConstant(kNaN);
  e.jaw = {kNaN, kNaN};
  e.jaw_sd = {kNaN, kNaN};
  e.contact_load.setConstant(kNaN);
  e.contact_load_sd.setConstant(kNaN);
  return e;
}

}  // namespace

ArmForceEstimator::ArmForceEstimator(Arm arm, const MotorMechanics& mechanics,
                                     const MotorMechanics& uncertainty,
                                     const raven::ArmKinematics& kinematics, GripLever grip)
    : arm_(arm),
      mechanics_(mechanics),
      uncertainty_(uncertainty),
      kinematics_(kinematics),
      grip_(grip),
      drive_(DriveTrain::raven2()),
      dac_(DacConversion::raven2(arm)) {
  if (!std::isfinite(grip.depth) || grip.depth == 0.0 || !(grip.spread >= 0.0) ||
      !std::isfinite(grip.spread)) {
    throw std::invalid_argument("grip depth " + std::to_string(grip.depth) + " m, spread " +
                                std::to_string(grip.spread) +
                                " m: the depth is a lever (finite, not 0), the spread >= 0");
  }
  to_joints_ = drive_.coupling(arm).transpose() * drive_.gearbox.cwiseInverse().asDiagonal();
}

ArmJoints ArmForceEstimator::appliedTorque(const recording::ArmSignals& row) const {
  ArmJoints applied;
  for (int i = 0; i < kJointCount; ++i) {
    const double counts = std::isfinite(row.dac(i))
                              ? row.dac(i)
                              : std::clamp(std::trunc(row.torque(i) * dac_.counts_per_torque(i)),
                                           -static_cast<double>(dac_.limit[std::size_t(i)]),
                                           static_cast<double>(dac_.limit[std::size_t(i)]));
    applied(i) = counts / dac_.counts_per_torque(i);
  }
  return applied;
}

Eigen::Matrix3d ArmForceEstimator::tipJacobian(const ArmJoints& joints) const {
  // The grip point, `depth` along the tool frame's x (the jaws), moves with the tool's twist.
  const Eigen::Vector3d lever = kinematics_.toolPose(joints).linear().col(0) * grip_.depth;
  Eigen::Matrix3d jacobian;
  for (int j = 0; j <= raven::kInsertion; ++j) {
    const auto twist = kinematics_.toolTwist(joints, ArmJoints::Unit(j));
    jacobian.col(j) = twist.head<3>() + twist.tail<3>().cross(lever);
  }
  return jacobian;
}

std::vector<MotorBalance> ArmForceEstimator::balances(
    const std::vector<double>& times, const std::vector<recording::ArmSignals>& rows) const {
  const std::size_t n = rows.size();
  // Each row's window: the rows kSpeedWindow either side (at least one, where there is one).
  std::vector<std::size_t> lo(n), hi(n);
  for (std::size_t k = 0; k < n; ++k) {
    lo[k] = k;
    while (lo[k] > 0 && k - lo[k] < kWindowRows && times[k] - times[lo[k]] < kSpeedWindow) {
      --lo[k];
    }
    hi[k] = k;
    while (hi[k] + 1 < n && hi[k] - k < kWindowRows && times[hi[k]] - times[k] < kSpeedWindow) {
      ++hi[k];
    }
  }
  // Each row's motor speed: the logged speed (mvel, the last cycle's turn) averaged over its
  // window; in a sparse recording (a window of the row alone) the row's own.
  std::vector<ArmJoints> speed(n, ArmJoints::Zero());
  for (std::size_t k = 0; k < n; ++k) {
    for (std::size_t j = lo[k]; j <= hi[k]; ++j) speed[k] += rows[j].motor_velocity;
    speed[k] /= static_cast<double>(hi[k] - lo[k] + 1);
  }
  const double count = 2.0 * M_PI / drive_.encoder_counts_per_motor_rev;
  std::vector<MotorBalance> out;
  out.reserve(n);
  CableStretch cables;  // the arm cables' stretch, following the motors from the first row
  for (std::size_t k = 0; k < n; ++k) {
    // The acceleration across the window, or across the rows either side where it holds no
    // other row.
    const bool alone = lo[k] == hi[k];
    const std::size_t a = alone && k > 0 ? k - 1 : lo[k];
    const std::size_t z = alone && k + 1 < n ? k + 1 : hi[k];
    const double span = times[z] - times[a];
    const ArmJoints acceleration =
        span > 0.0 ? ArmJoints((speed[z] - speed[a]) / span) : ArmJoints::Zero();
    MotorBalance b = balance(rows[k], speed[k], acceleration);
    if (k > 0 && finite(rows[k].motor) && finite(rows[k - 1].motor)) {
      cables.follow(mechanics_, rows[k].motor - rows[k - 1].motor);
    }
    if (b.finite) b.known += cables.torque(mechanics_);
    // Which way each motor slides at the row's instant, when the signals say: the cycle logged
    // turned two counts or more (one alone is an encoder flickering at a count's edge as often
    // as a turn), or the motor moved a count or more the same way on both sides of the row: 1
    // or -1. Else 0: it may stick, and then its friction may be anywhere in its band, whichever
    // way its controller pushes it (a load can hold it against the push).
    for (int i = 0; i < kJointCount; ++i) {
      const double now = rows[k].motor_velocity(i);
      const double before = rows[k].motor(i) - rows[lo[k]].motor(i);
      const double after = rows[hi[k]].motor(i) - rows[k].motor(i);
      if (std::abs(now) >= 1.5 * count / kCycle) {
        b.sliding(i) = std::copysign(1.0, now);
      } else if (before * after > 0.0 && std::min(std::abs(before), std::abs(after)) >= count) {
        b.sliding(i) = std::copysign(1.0, before);
      }
    }
    out.push_back(b);
  }
  return out;
}

MotorBalance ArmForceEstimator::balance(const recording::ArmSignals& row, const ArmJoints& speed,
                                        const ArmJoints& acceleration) const {
  MotorBalance b;
  b.applied = appliedTorque(row);
  b.joints = row.joints;
  b.finite = finite(row.joints) && finite(b.applied) && finite(speed) && finite(acceleration);
  if (!b.finite) return b;
  const MotorMechanics& m = mechanics_;
  const MotorMechanics& u = uncertainty_;
  const ArmJoints weight = gravityCompensation(arm_, row.joints, drive_);
  b.band = m.stickingFriction(b.applied);
  for (int i = 0; i < kJointCount; ++i) {
    b.known(i) = (1.0 + m.gravity_error(i)) * weight(i) + m.offset(i) +
                 m.inertia(i) * acceleration(i) + m.viscous(i) * speed(i) - b.applied(i);
    b.variance(i) = u.offset(i) * u.offset(i) + std::pow(u.gravity_error(i) * weight(i), 2) +
                    std::pow(u.inertia(i) * acceleration(i), 2) +
                    std::pow(u.viscous(i) * speed(i), 2);
  }
  return b;
}

void ArmForceEstimator::addFriction(std::vector<MotorBalance>& rows) const {
  const MotorMechanics& u = uncertainty_;
  for (int i = 0; i < kJointCount; ++i) {
    // A motor's load while it sticks is the load it slid under last (held still, what it
    // holds does not move): friction takes up what the applied torque changes, within its band.
    // Before its first slide, the band's middle. Either way the band is its uncertainty.
    std::optional<double> slid_under;
    for (MotorBalance& b : rows) {
      if (!b.finite) continue;
      const double s = b.sliding(i), band = b.band(i);
      if (s != 0.0) {
        b.friction(i) = s * band;
        const double sd = u.coulomb(i) + u.load_friction(i) * std::abs(b.applied(i));
        b.variance(i) += sd * sd;
        slid_under = b.known(i) + b.friction(i);
        continue;
      }
      b.friction(i) = slid_under ? std::clamp(*slid_under - b.known(i), -band, band) : 0.0;
      b.variance(i) += band * band / 3.0;  // uniform over the band
    }
  }
}

std::vector<ForceEstimate> ArmForceEstimator::estimate(
    const std::vector<double>& times, const std::vector<recording::ArmSignals>& rows) const {
  if (times.size() != rows.size()) {
    throw std::invalid_argument("force estimate: " + std::to_string(times.size()) + " times for " +
                                std::to_string(rows.size()) + " rows");
  }
  for (std::size_t k = 1; k < times.size(); ++k) {
    if (!(times[k] >= times[k - 1])) {
      throw std::invalid_argument(
          "data row " + std::to_string(k + 1) + ": time " + std::to_string(times[k]) +
          " s comes before the row before it (" + std::to_string(times[k - 1]) +
          " s): the motor speeds come from the rows around each row in time");
    }
  }
  std::vector<MotorBalance> motors = balances(times, rows);
  addFriction(motors);
  std::vector<ForceEstimate> out;
  out.reserve(motors.size());
  for (const MotorBalance& b : motors) out.push_back(b.finite ? estimateRow(b) : unknown());
  return out;
}

ForceEstimate ArmForceEstimator::estimateRow(const MotorBalance& b) const {
  ForceEstimate e;
  for (int i = 0; i < kJointCount; ++i) e.moving[std::size_t(i)] = b.sliding(i) != 0.0;
  // What the motors push against, through the cables onto the joints.
  e.contact_load = to_joints_ * (b.known + b.friction);
  const Eigen::Matrix<double, kJointCount, kJointCount> covariance =
      to_joints_ * b.variance.asDiagonal() * to_joints_.transpose();
  e.contact_load_sd = covariance.diagonal().cwiseSqrt();
  // At the grip: J^T F = the arm joints' contact loads, F the world's push on the tool.
  const Eigen::Matrix3d jacobian = tipJacobian(b.joints);
  const Eigen::FullPivLU<Eigen::Matrix3d> lu(jacobian.transpose());
  if (lu.isInvertible()) {
    const Eigen::Matrix3d inverse = lu.inverse();
    e.tip = -inverse * e.contact_load.head<3>();
    e.tip_sd =
        (inverse * covariance.topLeftCorner<3, 3>() * inverse.transpose()).diagonal().cwiseSqrt();
  } else {
    e.tip.setConstant(kNaN);
    e.tip_sd.setConstant(kNaN);
  }
  // A jaw's squeeze turns it open about its axis at the grip's lever.
  const double lever_sd = grip_.spread / std::sqrt(3.0);
  for (int j = 0; j < 2; ++j) {
    const int joint = raven::kJaw1 + j;
    const double squeeze = e.contact_load(joint) / grip_.depth;
    e.jaw[std::size_t(j)] = squeeze;
    e.jaw_sd[std::size_t(j)] =
        std::hypot(e.contact_load_sd(joint) / grip_.depth, squeeze * lever_sd / grip_.depth);
  }
  return e;
}

}  // namespace twin
