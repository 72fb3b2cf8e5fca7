#include "twin/drive_train.hpp"

#include <cmath>

namespace twin {

namespace {

// Radii in millimetres, as the firmware's defines.h gives them.
constexpr double kCable1050 = 1.19 / 2.0;  // the arm cables
constexpr double kCable1024 = 0.61 / 2.0;  // the tool cables
constexpr double kPulleyLink1 = 62.5 + kCable1050;
constexpr double kPulleyLink2 = 40.85 + kCable1050;
constexpr double kCapstanLink2Large = 7.82 + kCable1050;
constexpr double kCapstanLink2Small = 5.60 + kCable1050;
constexpr double kCapstanGp42 = 11.35 / 2.0;
constexpr double kCapstanGp32 = 4.7 + kCable1024;
constexpr double kCapstanTool = 10.6 + kCable1024;
constexpr double kGearboxGp42 = 49.0 / 4.0;  // the RE-40 motors of joints 1-3
constexpr double kGearboxGp32 = 26.0 / 7.0;  // the RE-30 motors of the tool
// The tool joints' ratios carry the firmware's empirical factors (asked 180, received 120, ...).
constexpr double kTool = kCapstanTool / kCapstanGp32 * kGearboxGp32;

}  // namespace

DriveTrain DriveTrain::raven2() {
  DriveTrain d;
  d.transmission << kPulleyLink1 / kCapstanGp42 * kGearboxGp42,
      kPulleyLink2 / kCapstanLink2Small * (kCapstanLink2Large / kCapstanGp42) * kGearboxGp42,
      1000.0 / kCapstanGp42 * kGearboxGp42,  // rad per metre: the capstan winds the cable
      kTool * 120.0 / 180.0, kTool * 200.0 / 180.0, kTool * 100.0 / 90.0, kTool * 100.0 / 90.0;
  return d;
}

double DriveTrain::countsPerMotorRadian() const {
  return encoder_counts_per_motor_rev / (2.0 * M_PI);
}

std::array<std::int32_t, raven::kJointCount> DriveTrain::encoderCounts(
    const raven::ArmJoints& motor) const {
  std::array<std::int32_t, raven::kJointCount> counts{};
  for (int i = 0; i < raven::kJointCount; ++i) {
    counts[static_cast<std::size_t>(i)] =
        static_cast<std::int32_t>(std::lround(motor(i) * countsPerMotorRadian()));
  }
  return counts;
}

}  // namespace twin
