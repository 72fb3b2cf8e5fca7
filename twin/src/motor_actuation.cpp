#include "twin/motor_actuation.hpp"

namespace twin {

MotorActuation::MotorActuation(TwinArms& arms, ambf_like::World& world, const DriveTrain& drive,
                               const ArmsMechanics& mechanics, double cycle)
    : arms_(arms),
      drives_{makeDrive(Arm::Left, arms, world, drive, mechanics[0], cycle),
              makeDrive(Arm::Right, arms, world, drive, mechanics[1], cycle)} {}

ArmDrive MotorActuation::makeDrive(Arm arm, TwinArms& arms, ambf_like::World& world,
                                   const DriveTrain& drive, const MotorMechanics& mechanics,
                                   double cycle) {
  if (!arms.articulated(arm)) {
    return ArmDrive(arm, drive, mechanics, cycle, arms.measured(arm),
                    {arms.hardStops(arm), arms.jawsMeet()});
  }
  const MotorMechanics& checked = mechanics.checked(arm);
  arms.placeJawsMeet(arm, checked.jawsMeetOffset(), checked.jawsMeetCompliance());
  return ArmDrive(arm, drive, WorldMotors(arm, drive, mechanics, arms, world), cycle);
}

void MotorActuation::drive(Arm arm, const ArmJoints& setpoint) {
  ArmDrive& d = drives_[raven::slot(arm)];
  d.cycle(setpoint);
  if (!d.movesTheLinks()) arms_.command(arm, d.linkPosition());
}

void MotorActuation::place(Arm arm, const ArmStart& start) {
  ArmDrive& d = drives_[raven::slot(arm)];
  d.place(start);
  if (!d.movesTheLinks()) arms_.command(arm, d.linkPosition());
}

std::string MotorActuation::fault() const {
  for (const ArmDrive& d : drives_) {
    if (!d.fault().empty()) return d.fault();
  }
  return {};
}

}  // namespace twin
