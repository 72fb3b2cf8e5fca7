#pragma once
// The twin's own actuators: stiff joint position servos that reach each setpoint within the
// cycle, read back exactly from the simulation; no motor torques or amplifier commands.

#include "twin/actuation.hpp"
#include "twin/drive_train.hpp"
#include "twin/twin_arms.hpp"
#include "twin/vocabulary.hpp"

namespace twin {

/// Setpoints go straight to the model's position servos; readings are the simulated joints.
class IdealActuation final : public Actuation {
 public:
  IdealActuation(twin::TwinArms& arms, DriveTrain drive) : arms_(arms), drive_(drive) {}
  void drive(raven::Arm arm, const raven::ArmJoints& setpoint) override;
  ActuatorReadings read(raven::Arm arm) const override;
  /// The joints go where the recorded motors put them.
  void place(raven::Arm arm, const ArmStart& start) override;
  /// Nothing beyond the World's joints.
  std::any state() const override { return {}; }
  void restore(const std::any& /*state*/) override {}

 private:
  twin::TwinArms& arms_;
  DriveTrain drive_;
};

}  // namespace twin
