#pragma once
// One Raven-II arm below its joints: each 1 ms cycle the encoders are read (4000 counts per motor
// turn, velocity as the one-cycle difference), the joint setpoint goes through the cable
// coupling to motor angles, the control software's law gives Tau and the DAC commands, and the
// motors move under the amplified torque: in the simulated world with the links they turn
// (WorldMotors), or alone with the links lumped into them (MotorAxes: the calibration's fast
// model, no simulator).

#include <Eigen/Core>
#include <optional>
#include <string>
#include <variant>

#include "raven/platform_profile.hpp"
#include "twin/actuation.hpp"
#include "twin/drive_train.hpp"
#include "twin/motor_controller.hpp"
#include "twin/motor_dynamics.hpp"
#include "twin/vocabulary.hpp"
#include "twin/world_motors.hpp"

namespace twin {

/// The mechanical stops the motors alone (MotorAxes) are held to: each joint's, and the jaws'
/// faces meeting (jaw1 + jaw2 >= jaws_meet). In a World the World's own stops hold the links.
struct ArmStops {
  std::optional<raven::JointLimits> joints;
  std::optional<double> jaws_meet;
};

/// One arm's motors, encoders and motor-level control.
class ArmDrive {
 public:
  /// At rest at `joints` with empty integrators, the joints held by `stops` (the motors move
  /// the joints through stiff cables, so a joint at its stop stops its motors too). Throws
  /// std::invalid_argument naming the arm and field of invalid mechanics.
  ArmDrive(Arm arm, const DriveTrain& drive, const MotorMechanics& mechanics, double cycle,
           const ArmJoints& joints, ArmStops stops = {});
  /// The motors in a World, at rest where its joints are, with empty integrators (the joints'
  /// stops are the World's).
  ArmDrive(Arm arm, const DriveTrain& drive, const WorldMotors& motors, double cycle);

  /// One control cycle toward `setpoint` (joints); the readings are this cycle's.
  const ActuatorReadings& cycle(const ArmJoints& setpoint);
  /// Puts the motors and the control state where a recording began.
  void place(const ArmStart& start);

  const ActuatorReadings& readings() const { return readings_; }
  /// Where the links are: the motors' exact angles through the cables.
  ArmJoints linkPosition() const;
  /// Whether the motors move the World's links themselves (WorldMotors), or the links must be
  /// put at linkPosition() (MotorAxes).
  bool movesTheLinks() const { return std::holds_alternative<WorldMotors>(motors_); }
  const MotorController& controller() const { return controller_; }
  /// Why the robot must stop (the amplifiers' soft e-stop), or empty. While set, the
  /// amplifiers get nothing.
  const std::string& fault() const { return fault_; }
  /// Powers the amplifiers again (the robot was enabled after its e-stop).
  void clearFault() { fault_.clear(); }

 private:
  ArmDrive(Arm arm, const DriveTrain& drive, double cycle, ArmStops stops,
           std::variant<MotorAxes, WorldMotors> motors);
  void sense();
  /// A joint that passed its stop is put back on it, its speed into the stop gone (an
  /// inelastic stop), and the motors with it; jaws closed past each other are parted alike
  /// where their faces are rigid.
  void holdAtStops();
  /// How far (rad of jaw1 + jaw2) the jaws the motors alone hold are open from where their
  /// faces meet (< 0: closed past it). Only with a jaws' stop.
  double jawsGap(const MotorAxes& motors) const;
  /// The torques (at the gearbox outputs) with which faces that give (MotorMechanics::
  /// face_compliance) push the jaws apart this cycle, the motors driven by `applied`: the
  /// World's soft stop (CoupledStop) on the motors alone, solved on their velocity at the
  /// cycle's end, so it takes energy out and never puts it in.
  ArmJoints facesPush(const ArmJoints& applied) const;

  Arm arm_;
  DriveTrain drive_;
  double cycle_;
  ArmStops stops_;
  std::variant<MotorAxes, WorldMotors> motors_;
  MotorController controller_;
  /// d(motor)/d(joint): joint loads are its transpose times motor torques.
  Eigen::Matrix<double, kJointCount, kJointCount> coupling_;
  /// The jaws' opening (jaw1 + jaw2) per motor angle, and the torques (at the gearbox outputs)
  /// that press both jaws open with 1 N m: the faces' row, in the motors' terms.
  ArmJoints opening_per_motor_, opening_torques_;
  ActuatorReadings readings_;
  ArmJoints last_count_;  ///< the previous cycle's quantised motor angles
  std::string fault_;
};

}  // namespace twin
