#include "twin/recorded_start.hpp"

#include <stdexcept>

#include "twin/motor_controller.hpp"

namespace twin {

RecordedStart recordedStart(const raven::PerArm<recording::ArmSignals>& first_row) {
  RecordedStart out;
  for (Arm arm : raven::kArms) {
    const auto a = raven::slot(arm);
    const recording::ArmSignals& s = first_row[a];
    ArmStart& start = out.arms[a];
    start.motor_position = s.motor;
    start.motor_velocity = s.motor_velocity;
    const MotorController law(arm, DriveTrain::raven2());
    start.integrators =
        law.integratorsGiving(s.torque, s.motor_setpoint - s.motor, s.motor_velocity, s.joints);
    out.setpoint[a] = s.joint_setpoint;
  }
  return out;
}

RecordedStart recordedStart(const recording::RsRecording& rs) {
  if (rs.rows.empty()) {
    throw recording::RecordingError(rs.path.string() + ": no rows to start from");
  }
  const raven::PerArm<recording::ArmSignals> first{rs.signals(0, Arm::Left),
                                                   rs.signals(0, Arm::Right)};
  for (const auto& s : first) {
    for (const ArmJoints* v : {&s.joints, &s.joint_setpoint, &s.motor, &s.motor_velocity,
                               &s.motor_setpoint, &s.torque}) {
      if (!v->allFinite()) {
        throw recording::RecordingError(
            rs.path.string() +
            ": row 1 has no finite motor signals (jpos, jpos_d, mpos, mvel, mpos_d, Tau): not a "
            "recording of the physical robot or the twin (AMBF's log none)");
      }
    }
  }
  return recordedStart(first);
}

void startAt(TwinPlatform& twin, const RecordedStart& start) {
  for (Arm arm : raven::kArms) {
    const auto result = twin.send(bridge::MoveJp{arm, start.setpoint[raven::slot(arm)]});
    if (!result) {
      throw std::runtime_error("cannot start where the recording began: " + result.note);
    }
  }
  const double deadline = twin.now() + 30.0;
  while (twin.operatingStatus().is_busy && twin.now() < deadline) twin.advance(0.01);
  twin.advance(0.5);  // settled
  for (Arm arm : raven::kArms) twin.place(arm, start.arms[raven::slot(arm)]);
}

}  // namespace twin
