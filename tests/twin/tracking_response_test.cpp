// The tracking response in front of an actuation: latency, the second-order response against its
// closed form, the limits, pass-through, and calibration profiles read with bad input named.

#include "twin/tracking_response.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "test_files.hpp"
#include "twin/calibration_profile.hpp"

namespace {

using raven::Arm;
using raven::ArmJoints;
using twin::TrackingParams;

/// The actuation behind the response: remembers what it was last driven to.
class DrivenTo final : public twin::Actuation {
 public:
  void drive(Arm arm, const ArmJoints& setpoint, const ArmJoints& velocity) override {
    position[static_cast<std::size_t>(raven::index(arm))] = setpoint;
    speed[static_cast<std::size_t>(raven::index(arm))] = velocity;
  }
  twin::ActuatorReadings read(Arm) const override { return {}; }
  std::array<ArmJoints, 2> position{}, speed{};
};

struct Rig {
  explicit Rig(const TrackingParams& p) {
    auto inner = std::make_unique<DrivenTo>();
    driven = inner.get();
    response = std::make_unique<twin::TrackingActuation>(std::move(inner), p, 0.001);
  }
  /// One cycle with `setpoint` on the left arm; returns what reached the actuation.
  ArmJoints cycle(const ArmJoints& setpoint) {
    response->drive(Arm::Left, setpoint, ArmJoints::Zero());
    return driven->position[0];
  }
  DrivenTo* driven = nullptr;
  std::unique_ptr<twin::TrackingActuation> response;
};

TEST(TrackingResponse, WithoutBandwidthItIsAPureDelayOfTheLatency) {
  TrackingParams p;
  p.latency_cycles = 3.0;
  Rig rig(p);
  EXPECT_EQ(rig.cycle(ArmJoints::Zero()), ArmJoints::Zero());
  const ArmJoints step = ArmJoints::Constant(0.1);
  for (int k = 1; k <= 3; ++k) EXPECT_EQ(rig.cycle(step), ArmJoints::Zero()) << "cycle " << k;
  EXPECT_EQ(rig.cycle(step), step) << "seen exactly 3 cycles later";
}

TEST(TrackingResponse, AFractionalLatencyInterpolatesBetweenCycles) {
  TrackingParams p;
  p.latency_cycles = 1.25;
  Rig rig(p);
  rig.cycle(ArmJoints::Zero());
  EXPECT_EQ(rig.cycle(ArmJoints::Constant(1.0)), ArmJoints::Zero());
  EXPECT_NEAR(rig.cycle(ArmJoints::Constant(1.0))(0), 0.75, 1e-15);
  EXPECT_NEAR(rig.cycle(ArmJoints::Constant(1.0))(0), 1.0, 1e-15);
}

TEST(TrackingResponse, ACriticallyDampedJointFollowsItsClosedFormStepResponse) {
  TrackingParams p;
  p.bandwidth_hz = ArmJoints::Constant(5.0);
  p.damping_ratio = ArmJoints::Constant(1.0);
  Rig rig(p);
  rig.cycle(ArmJoints::Zero());
  const double w = 2.0 * M_PI * 5.0;
  double worst = 0.0;
  for (int k = 1; k <= 400; ++k) {
    const double x = rig.cycle(ArmJoints::Constant(0.01))(2);
    const double t = 0.001 * k;
    const double exact = 0.01 * (1.0 - (1.0 + w * t) * std::exp(-w * t));
    worst = std::max(worst, std::abs(x - exact));
  }
  // Backward Euler at w dt = 0.031: within 2 % of the step all the way, never overshooting.
  EXPECT_LT(worst, 0.0002);
  EXPECT_NEAR(rig.driven->position[0](2), 0.01, 1e-6) << "settled after 0.4 s";
}

TEST(TrackingResponse, FrictionHoldsAJointUntilTheErrorExceedsItsDeadband) {
  TrackingParams p;
  p.bandwidth_hz = ArmJoints::Constant(10.0);
  p.friction_deadband = ArmJoints::Constant(0.001);
  Rig rig(p);
  rig.cycle(ArmJoints::Zero());
  for (int k = 0; k < 200; ++k) rig.cycle(ArmJoints::Constant(0.0009));
  EXPECT_EQ(rig.driven->position[0](0), 0.0) << "0.9 of the deadband: stuck";
  for (int k = 0; k < 500; ++k) rig.cycle(ArmJoints::Constant(0.01));
  const double rest = rig.driven->position[0](0);
  EXPECT_GE(rest, 0.01 - 0.001 * 1.001) << "broke away and slid to within the deadband";
  EXPECT_LT(rest, 0.01);
  EXPECT_EQ(rig.driven->speed[0](0), 0.0) << "and stuck again";
}

TEST(TrackingResponse, VelocityAndAccelerationLimitsHold) {
  TrackingParams p;
  p.bandwidth_hz = ArmJoints::Constant(50.0);
  p.max_velocity = ArmJoints::Constant(0.2);
  p.max_acceleration = ArmJoints::Constant(10.0);
  Rig rig(p);
  rig.cycle(ArmJoints::Zero());
  double previous_v = 0.0;
  for (int k = 0; k < 300; ++k) {
    rig.cycle(ArmJoints::Constant(1.0));
    const double v = rig.driven->speed[0](0);
    ASSERT_LE(std::abs(v), 0.2 + 1e-12);
    ASSERT_LE(std::abs(v - previous_v), 10.0 * 0.001 + 1e-12);
    previous_v = v;
  }
  EXPECT_NEAR(rig.driven->speed[0](0), 0.2, 1e-12) << "cruising at the limit";
}

TEST(TrackingResponse, TheArmsAreIndependent) {
  TrackingParams p;
  p.latency_cycles = 2.0;
  Rig rig(p);
  rig.response->drive(Arm::Right, ArmJoints::Constant(0.5), ArmJoints::Zero());
  rig.cycle(ArmJoints::Zero());
  EXPECT_EQ(rig.driven->position[1], ArmJoints::Constant(0.5)) << "starts at rest where it is";
  EXPECT_EQ(rig.driven->position[0], ArmJoints::Zero());
}

TEST(TrackingResponse, InvalidParametersAreRefusedNamingTheField) {
  TrackingParams p;
  p.damping_ratio(4) = 0.0;
  try {
    twin::TrackingActuation a(std::make_unique<DrivenTo>(), p, 0.001);
    FAIL() << "accepted a zero damping ratio";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("damping_ratio[4] (wrist)"), std::string::npos)
        << e.what();
  }
  p = {};
  p.latency_cycles = std::nan("");
  EXPECT_THROW(twin::TrackingActuation(std::make_unique<DrivenTo>(), p, 0.001),
               std::invalid_argument);
}

std::filesystem::path writeProfile(const test_support::TempDir& dir, const std::string& text) {
  const auto file = dir.path() / "calibration.yaml";
  std::ofstream(file) << text;
  return file;
}

TEST(CalibrationProfile, ReadsTheResponseAndTheReplayTiming) {
  test_support::TempDir dir;
  const auto profile = twin::CalibrationProfile::load(writeProfile(dir, R"(
tracking:
  latency_cycles: 8.5
  bandwidth_hz: [20, 21, 4.5, 30, 30, 30, 30]
  damping_ratio: [1, 1, 1.05, 0.9, 0.9, 0.9, 0.9]
  friction_deadband: [0.001, 0.001, 0.0002, 0, 0, 0, 0]
  max_velocity: [1, 1, 0.1, 2, 2, 2, 2]
replay:
  iteration_overhead: 0.001
fit:
  notes: [anything]
)"));
  EXPECT_EQ(profile.tracking.latency_cycles, 8.5);
  EXPECT_EQ(profile.tracking.bandwidth_hz(2), 4.5);
  EXPECT_EQ(profile.tracking.damping_ratio(3), 0.9);
  EXPECT_EQ(profile.tracking.max_velocity(2), 0.1);
  EXPECT_EQ(profile.tracking.friction_deadband(2), 0.0002);
  EXPECT_TRUE(std::isinf(profile.tracking.max_acceleration(0))) << "optional: unlimited";
  EXPECT_EQ(profile.iteration_overhead, 0.001);
}

TEST(CalibrationProfile, BadValuesAndUnknownKeysAreNamed) {
  test_support::TempDir dir;
  auto errorOf = [&](const std::string& text) {
    return test_support::loadErrorOf(
        [&] { twin::CalibrationProfile::load(writeProfile(dir, text)); });
  };
  const std::string good_lists =
      "  bandwidth_hz: [20, 20, 4, 20, 20, 20, 20]\n  damping_ratio: [1, 1, 1, 1, 1, 1, 1]\n";
  EXPECT_NE(errorOf("tracking:\n  latency_cycles: 1\n  bandwidth_hz: [20, 20, -4, 20, 20, 20, "
                    "20]\n  damping_ratio: [1, 1, 1, 1, 1, 1, 1]\n")
                .find(":3: tracking/bandwidth_hz: every value must be > 0"),
            std::string::npos);
  EXPECT_NE(errorOf("tracking:\n  latency_cycles: 1\n  bandwidth_hz: [20, 20]\n  damping_ratio: "
                    "[1, 1, 1, 1, 1, 1, 1]\n")
                .find("bandwidth_hz"),
            std::string::npos);
  EXPECT_NE(errorOf("tracking:\n  latency_cycles: 1\n  bandwith_hz: [1]\n" + good_lists)
                .find("bandwith_hz"),
            std::string::npos);
  EXPECT_NE(errorOf("tracking:\n  latency_cycles: .nan\n" + good_lists).find("latency_cycles"),
            std::string::npos);
  EXPECT_NE(errorOf("tracking:\n  latency_cycles: 1\n" + good_lists +
                    "replay: {iteration_overhead: -1}\n")
                .find("iteration_overhead"),
            std::string::npos);
  EXPECT_NE(errorOf("tracking: [1, 2\n").find("calibration.yaml"), std::string::npos);
}

}  // namespace
