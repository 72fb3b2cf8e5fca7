#include "twin/motor_actuation.hpp"

namespace twin {

MotorActuation::MotorActuation(TwinArms& arms, const DriveTrain& drive,
                               const ArmsMechanics& mechanics, double cycle)
    : arms_(arms),
      drives_{ArmDrive(Arm::Left, drive, mechanics[0], cycle, arms.measured(Arm::Left),
                       arms.hardStops(Arm::Left)),
              ArmDrive(Arm::Right, drive, mechanics[1], cycle, arms.measured(Arm::Right),
                       arms.hardStops(Arm::Right))} {}

void MotorActuation::drive(Arm arm, const ArmJoints& setpoint, const ArmJoints& /*velocity*/) {
  ArmDrive& d = drives_[index(arm)];
  d.cycle(setpoint);
  arms_.command(arm, d.linkPosition());
}

void MotorActuation::place(Arm arm, const ArmStart& start) {
  ArmDrive& d = drives_[index(arm)];
  d.place(start);
  arms_.command(arm, d.linkPosition());
}

std::string MotorActuation::fault() const {
  for (const ArmDrive& d : drives_) {
    if (!d.fault().empty()) return d.fault();
  }
  return {};
}

}  // namespace twin
