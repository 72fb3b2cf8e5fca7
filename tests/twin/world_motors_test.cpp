// The motors drive the simulated links through the cables and carry what the links carry:
// checked against the loads an ideal joint servo measures on the same links at the same pose.

#include <gtest/gtest.h>

#include <array>

#include "bridge/raven_state.hpp"
#include "twin/calibration_profile.hpp"
#include "twin_fixtures.hpp"

namespace {

using raven::Arm;
using raven::ArmJoints;

/// The shipped mechanics without friction or gravity error: at rest the motors then carry the
/// links' weight alone.
twin::TwinOptions frictionlessMotors() {
  twin::TwinOptions options;
  options.motors = twin::CalibrationProfile::shipped().mechanics;
  for (auto& m : *options.motors) {
    m.coulomb.setZero();
    m.load_friction.setZero();
    m.gravity_error.setZero();
  }
  return options;
}

ArmJoints loggedTau(const twin::TwinPlatform& twin, Arm arm) {
  const auto state = twin.ravenState();
  ArmJoints tau;
  for (int i = 0; i < raven::kJointCount; ++i) {
    tau(i) = state->tau[static_cast<std::size_t>(bridge::ravenStateIndex(arm, i))];
  }
  return tau;
}

/// Motor torques (at the gearbox outputs) that give the joint loads `joint` through the
/// cables: joint loads are coupling^T (tau / gearbox).
ArmJoints throughTheCables(const twin::DriveTrain& drive, Arm arm, const ArmJoints& joint) {
  Eigen::Matrix<double, raven::kJointCount, raven::kJointCount> c;
  for (int j = 0; j < raven::kJointCount; ++j) c.col(j) = drive.toMotor(arm, ArmJoints::Unit(j));
  return c.transpose().partialPivLu().solve(joint).cwiseProduct(drive.gearbox);
}

TEST(WorldMotors, HeldStillTheMotorsCarryTheLinksWeightThroughTheCables) {
  auto motors = test_support::readyTwin(frictionlessMotors());
  motors->advance(3.0);  // the integrators take up what the firmware's model of the weight misses
  // Held, a motor hunts by an encoder count about its setpoint (kp x 1.6 mrad is about 0.015
  // N m on a shoulder): its torque balances the load on average, over a second.
  std::array<ArmJoints, 2> meanTau{ArmJoints::Zero(), ArmJoints::Zero()};
  constexpr int kCycles = 1000;
  for (int k = 0; k < kCycles; ++k) {
    motors->advance(0.001);
    for (Arm arm : raven::kArms) {
      meanTau[static_cast<std::size_t>(raven::index(arm))] += loggedTau(*motors, arm) / kCycles;
    }
  }
  auto ideal = test_support::readyTwin();
  const auto drive = twin::DriveTrain::raven2();
  for (Arm arm : raven::kArms) {
    const ArmJoints held = motors->measuredJs(arm).position;
    ideal->send(bridge::ServoJp{arm, held});
  }
  ideal->advance(1.0);
  for (Arm arm : raven::kArms) {
    // The ideal servo holds the same pose with the links' weight as its joint efforts.
    ASSERT_LT(
        (ideal->measuredJs(arm).position - motors->measuredJs(arm).position).cwiseAbs().maxCoeff(),
        1e-6);
    const ArmJoints expected = throughTheCables(drive, arm, ideal->measuredJs(arm).effort);
    const ArmJoints tau = meanTau[static_cast<std::size_t>(raven::index(arm))];
    const double scale = expected.cwiseAbs().maxCoeff();
    for (int i = 0; i < raven::kJointCount; ++i) {
      EXPECT_NEAR(tau(i), expected(i), 0.05 * std::abs(expected(i)) + 1e-3 * scale)
          << raven::armName(arm) << " " << raven::kJointNames[static_cast<std::size_t>(i)];
    }
  }
}

}  // namespace
