#pragma once
// One Raven-II arm's motors moving in the simulated world: their torque goes through the cable
// coupling onto the arm's joints (an ambf_like::Transmission), their rotors' inertia and friction
// move with the links in one solve, and the encoders read the links' angles through the cables.
// What the links touch (a ring, the other jaw, the board, a joint's stop) therefore loads them.

#include <Eigen/LU>

#include "ambf_like/world.hpp"
#include "twin/drive_train.hpp"
#include "twin/motor_dynamics.hpp"
#include "twin/twin_arms.hpp"
#include "twin/vocabulary.hpp"

namespace twin {

/// The motors of one arm as a transmission on its joints in a World.
class WorldMotors {
 public:
  /// The rotors carry what `mechanics`' inertia leaves of the links' inertia as the motors feel
  /// it at the arms' pose now (the fitted inertia is the motor's whole load). Throws
  /// std::invalid_argument when the arm's joints are not one articulation of `world`.
  WorldMotors(Arm arm, const DriveTrain& drive, const MotorMechanics& mechanics, TwinArms& arms,
              ambf_like::World& world);

  /// `torque` (at the gearbox outputs) from the next world step on, against the weight the
  /// calibration fitted: `gravity_load` (the firmware's estimate) times one plus the fitted
  /// gravity error, whatever the model's links weigh.
  void step(const ArmJoints& torque, const ArmJoints& gravity_load, double seconds);
  ArmJoints position() const;  ///< motor rad, the links' angles through the cables
  /// Puts the arm's joints where these motor angles and speeds put them.
  void place(const ArmJoints& position, const ArmJoints& velocity);

 private:
  Arm arm_;
  DriveTrain drive_;
  MotorMechanics mechanics_;
  TwinArms* arms_;
  ambf_like::Transmission* transmission_;
  /// coupling^-T: joint torques to the motor torques that give them.
  Eigen::Matrix<double, kJointCount, kJointCount> weight_to_motors_;
  CableStretch cables_;
  ArmJoints cables_followed_to_;  ///< the motor angles the cables' stretch has followed to
};

}  // namespace twin
