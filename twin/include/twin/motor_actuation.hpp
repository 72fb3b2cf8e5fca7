#pragma once
// The Raven-II's actuation below the joints in a simulated world: each arm's ArmDrive runs the
// motors and their control software. Where an arm is an articulation (reduced coordinates), its
// motors drive the links through the cables and the links' loads (weight, contact, stops) come
// back to them (WorldMotors); elsewhere (maximal coordinates) the links follow the motors'
// angles and nothing they touch reaches the motors.

#include <array>
#include <string>

#include "twin/actuation.hpp"
#include "twin/arm_drive.hpp"
#include "twin/twin_arms.hpp"
#include "twin/vocabulary.hpp"

namespace twin {

/// The mechanics of both arms' motors (per raven::slot(arm)).

/// Motor-level actuation of both arms of a TwinArms.
class MotorActuation final : public Actuation {
 public:
  /// Starts at rest at the arms' current joints with empty integrators. Throws
  /// std::invalid_argument naming the arm and field of invalid mechanics.
  MotorActuation(TwinArms& arms, ambf_like::World& world, const DriveTrain& drive,
                 const ArmsMechanics& mechanics, double cycle);
  void drive(Arm arm, const ArmJoints& setpoint) override;
  ActuatorReadings read(Arm arm) const override { return drives_[raven::slot(arm)].readings(); }
  std::string fault() const override;
  void clearFault() override {
    for (ArmDrive& d : drives_) d.clearFault();
  }

  void place(Arm arm, const ArmStart& start) override;
  /// Both arms' drives: motors, controllers, encoders.
  std::any state() const override { return drives_; }
  void restore(const std::any& state) override {
    drives_ = std::any_cast<const raven::PerArm<ArmDrive>&>(state);
  }

 private:
  static ArmDrive makeDrive(Arm arm, TwinArms& arms, ambf_like::World& world,
                            const DriveTrain& drive, const MotorMechanics& mechanics, double cycle);

  TwinArms& arms_;
  raven::PerArm<ArmDrive> drives_;
};

}  // namespace twin
