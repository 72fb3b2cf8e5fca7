// analysis::errorWindows: where in a session one motor's twin-vs-robot difference sits.

#include "analysis/error_windows.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace error_windows_test {

using analysis::ActuatorSignal;
using analysis::ActuatorTrace;

/// A trace of `rows` rows 20 ms apart, every signal zero.
ActuatorTrace quietTrace(std::size_t rows) {
  ActuatorTrace t;
  for (std::size_t r = 0; r < rows; ++r) {
    t.time.push_back(0.02 * static_cast<double>(r));
    recording::ArmSignals s;
    s.joints = s.joint_setpoint = s.motor = s.motor_velocity = s.motor_setpoint = s.torque = s.dac =
        raven::ArmJoints::Zero();
    for (auto& arm : t.arms) arm.push_back(s);
  }
  return t;
}

TEST(ErrorWindows, AnErrorInSomeRowsOfOneMotorShowsInItsWindowsAlone) {
  const ActuatorTrace robot = quietTrace(250);
  ActuatorTrace twin = robot;
  const auto right = raven::slot(raven::Arm::Right);
  for (std::size_t r = 120; r < 150; ++r) twin.arms[right][r].torque(raven::kJaw1) = 0.01;
  twin.arms[right][10].torque(raven::kJaw1) = -0.03;  // the sign does not cancel
  twin.arms[right][60].torque(raven::kJaw2) = 1.0;    // another motor: not counted
  const auto w = analysis::errorWindows({twin}, {robot, robot}, ActuatorSignal::Torque,
                                        raven::Arm::Right, raven::kJaw1, 100);
  ASSERT_EQ(w.size(), 3u);  // 0-99, 100-199 and the last 50 rows
  EXPECT_EQ(w[2].first_row, 200u);
  EXPECT_EQ(w[2].last_row, 249u);
  EXPECT_DOUBLE_EQ(w[1].start, 2.0);
  EXPECT_DOUBLE_EQ(w[1].end, 3.98);
  // Per trial: 0.03 in window 0, 30 x 0.01 = 0.3 in window 1; both trials alike.
  EXPECT_NEAR(w[0].share, 0.03 / 0.33, 1e-12);
  EXPECT_NEAR(w[1].share, 0.3 / 0.33, 1e-12);
  EXPECT_EQ(w[2].share, 0.0);
  EXPECT_NEAR(w[1].mean, 0.3 / 100.0, 1e-12);
  // The left arm's jaw is untouched.
  for (const auto& window : analysis::errorWindows({twin}, {robot, robot}, ActuatorSignal::Torque,
                                                   raven::Arm::Left, raven::kJaw1, 100)) {
    EXPECT_EQ(window.share, 0.0);
  }
}

TEST(ErrorWindows, RowsArePairedByIndexOverTheRowsEveryTraceHas) {
  ActuatorTrace robot = quietTrace(120), longer = quietTrace(300);
  for (std::size_t r = 0; r < 300; ++r) longer.arms[0][r].motor(raven::kShoulder) = 1.0;
  const auto w = analysis::errorWindows({longer}, {robot}, ActuatorSignal::MotorPosition,
                                        raven::Arm::Left, raven::kShoulder, 50);
  ASSERT_EQ(w.size(), 3u);
  EXPECT_EQ(w.back().last_row, 119u);
  EXPECT_NEAR(w[0].mean, 180.0 / M_PI, 1e-9);  // in the logged unit, degrees
  EXPECT_NEAR(w[0].share + w[1].share + w[2].share, 1.0, 1e-12);
}

TEST(ErrorWindows, MeaninglessQuestionsAreRefused) {
  const ActuatorTrace t = quietTrace(10);
  EXPECT_THROW(analysis::errorWindows({t}, {}, ActuatorSignal::Torque, raven::Arm::Left, 0, 5),
               std::invalid_argument);
  EXPECT_THROW(
      analysis::errorWindows({t, t}, {t, t, t}, ActuatorSignal::Torque, raven::Arm::Left, 0, 5),
      std::invalid_argument);
  EXPECT_THROW(analysis::errorWindows({t}, {t}, ActuatorSignal::Torque, raven::Arm::Left,
                                      raven::kJointCount, 5),
               std::invalid_argument);
  EXPECT_THROW(analysis::errorWindows({t}, {t}, ActuatorSignal::Torque, raven::Arm::Left, 0, 0),
               std::invalid_argument);
}

}  // namespace error_windows_test
