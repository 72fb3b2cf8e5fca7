#pragma once
// The Raven-II control software's gravity compensation (uw-biorobotics/raven2 grav_comp.cpp;
// raven2-actuation.md §3): the torque its motors add to hold the first three links against
// gravity, from its own link masses and centres of mass.

#include "twin/drive_train.hpp"
#include "twin/vocabulary.hpp"

namespace twin {

/// Per joint, on the gearbox-output scale the robot logs as Tau (N m); the tool joints get 0.
/// `joints`: the measured joints (rad, m).
ArmJoints gravityCompensation(Arm arm, const ArmJoints& joints, const DriveTrain& drive);

}  // namespace twin
