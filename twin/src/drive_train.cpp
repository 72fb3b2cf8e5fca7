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
constexpr double kGearboxGp42 = 49.0 / 4.0;  // the RE 40 motors of joints 1-3
constexpr double kGearboxGp32 = 26.0 / 7.0;  // the RE 30 motors of the tool
// The tool joints' ratios carry the firmware's empirical factors (asked 180, received 120, ...).
constexpr double kTool = kCapstanTool / kCapstanGp32 * kGearboxGp32;

}  // namespace

DriveTrain DriveTrain::raven2() {
  DriveTrain d;
  d.transmission << kPulleyLink1 / kCapstanGp42 * kGearboxGp42,
      kPulleyLink2 / kCapstanLink2Small * (kCapstanLink2Large / kCapstanGp42) * kGearboxGp42,
      1000.0 / kCapstanGp42 * kGearboxGp42,  // rad per metre: the capstan winds the cable
      kTool * 120.0 / 180.0, kTool * 200.0 / 180.0, kTool * 100.0 / 90.0, kTool * 100.0 / 90.0;
  d.gearbox << kGearboxGp42, kGearboxGp42, kGearboxGp42, kGearboxGp32, kGearboxGp32, kGearboxGp32,
      kGearboxGp32;
  d.shoulder_to_elbow = 0.14545;
  d.shoulder_to_insertion = 0.0077973826;
  d.elbow_to_insertion = 0.008077387;
  d.tool_drag = (kGearboxGp32 / kGearboxGp42) * (kCapstanGp42 / kCapstanGp32);
  d.wrist_to_jaws = 0.5;
  return d;
}

ArmJoints DriveTrain::toMotor(Arm arm, const ArmJoints& q, double insertion_motor) const {
  const double drag = toolSign(arm) * tool_drag * insertion_motor;
  const ArmJoints& t = transmission;
  ArmJoints m;
  m(raven::kShoulder) = t(raven::kShoulder) * q(raven::kShoulder);
  m(raven::kElbow) =
      t(raven::kElbow) * (q(raven::kElbow) + shoulder_to_elbow * q(raven::kShoulder));
  m(raven::kInsertion) = insertionMotor(q);
  m(raven::kRoll) = t(raven::kRoll) * q(raven::kRoll) + drag;
  m(raven::kWrist) = t(raven::kWrist) * q(raven::kWrist) + drag;
  // Jaw 1's cable runs the other way (OPPOSE_GRIP).
  m(raven::kJaw1) = t(raven::kJaw1) * (q(raven::kJaw1) + wrist_to_jaws * q(raven::kWrist)) - drag;
  m(raven::kJaw2) = t(raven::kJaw2) * (q(raven::kJaw2) - wrist_to_jaws * q(raven::kWrist)) + drag;
  return m;
}

ArmJoints DriveTrain::toMotor(Arm arm, const ArmJoints& q) const {
  return toMotor(arm, q, insertionMotor(q));
}

Eigen::Matrix<double, kJointCount, kJointCount> DriveTrain::coupling(Arm arm) const {
  Eigen::Matrix<double, kJointCount, kJointCount> c;
  for (int j = 0; j < kJointCount; ++j) c.col(j) = toMotor(arm, ArmJoints::Unit(j));
  return c;
}

double DriveTrain::insertionMotor(const ArmJoints& q) const {
  return transmission(raven::kInsertion) *
         (q(raven::kInsertion) + shoulder_to_insertion * q(raven::kShoulder) +
          elbow_to_insertion * q(raven::kElbow));
}

ArmJoints DriveTrain::toJoints(Arm arm, const ArmJoints& m) const {
  const double drag = toolSign(arm) * tool_drag * m(raven::kInsertion);
  const ArmJoints& t = transmission;
  ArmJoints q;
  q(raven::kShoulder) = m(raven::kShoulder) / t(raven::kShoulder);
  q(raven::kElbow) = m(raven::kElbow) / t(raven::kElbow) - shoulder_to_elbow * q(raven::kShoulder);
  q(raven::kInsertion) = m(raven::kInsertion) / t(raven::kInsertion) -
                         shoulder_to_insertion * q(raven::kShoulder) -
                         elbow_to_insertion * q(raven::kElbow);
  q(raven::kRoll) = (m(raven::kRoll) - drag) / t(raven::kRoll);
  q(raven::kWrist) = (m(raven::kWrist) - drag) / t(raven::kWrist);
  q(raven::kJaw1) = (m(raven::kJaw1) + drag) / t(raven::kJaw1) - wrist_to_jaws * q(raven::kWrist);
  q(raven::kJaw2) = (m(raven::kJaw2) - drag) / t(raven::kJaw2) + wrist_to_jaws * q(raven::kWrist);
  return q;
}

double DriveTrain::countsPerMotorRadian() const {
  return encoder_counts_per_motor_rev / (2.0 * M_PI);
}

ArmJoints DriveTrain::quantise(const ArmJoints& motor) const {
  const double c = countsPerMotorRadian();
  return (motor * c).array().round().matrix() / c;
}

std::array<std::int32_t, kJointCount> DriveTrain::encoderCounts(const ArmJoints& motor) const {
  std::array<std::int32_t, kJointCount> counts{};
  for (int i = 0; i < kJointCount; ++i) {
    counts[static_cast<std::size_t>(i)] =
        static_cast<std::int32_t>(std::lround(motor(i) * countsPerMotorRadian()));
  }
  return counts;
}

}  // namespace twin
