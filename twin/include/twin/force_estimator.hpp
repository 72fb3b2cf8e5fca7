#pragma once
// The twin's model of an arm read backwards: from the signals a Raven-II logs of its motors (the
// DAC counts or Tau, the motor angles, the joints) to what its tool pushes on and what its jaws
// squeeze, with the uncertainty the motors' friction and the calibration leave (docs/forces.md).

#include <Eigen/Core>
#include <array>
#include <vector>

#include "raven/arm_kinematics.hpp"
#include "recording/recording_io.hpp"
#include "twin/drive_train.hpp"
#include "twin/motor_controller.hpp"
#include "twin/motor_dynamics.hpp"
#include "twin/vocabulary.hpp"

namespace twin {

/// Where along the jaws the gripped object sits: the lever its squeeze acts on, and the point the
/// tool's force is taken at.
struct GripLever {
  /// m along the jaws from their axis (the tool frame's x; below 0, behind it on the wrist):
  /// the main job's grip on a ring's wall by default
  double depth = 0.007;
  double spread = 0.002;  ///< m either side of it the contact may lie (a uniform band)
};

/// One row's estimate for one arm; NaN where the row lacks a signal or the arm's pose cannot
/// tell (a singular Jacobian).
struct ForceEstimate {
  /// N: what the tool pushes on at the grip point (GripLever's depth along the jaws), in the
  /// kinematics' frame (the twin's world frame, as its cf files)
  Eigen::Vector3d tip = Eigen::Vector3d::Zero();
  Eigen::Vector3d tip_sd = Eigen::Vector3d::Zero();  ///< its standard deviation, per axis
  std::array<double, 2> jaw{};                       ///< N: each jaw's squeeze (pushing it open)
  std::array<double, 2> jaw_sd{};
  ArmJoints contact_load = ArmJoints::Zero();  ///< what contacts put on the joints (N m; N)
  ArmJoints contact_load_sd = ArmJoints::Zero();
  std::array<bool, kJointCount> moving{};  ///< per motor: sliding (friction known) or maybe stuck
};

/// One row of an arm's motors: what the model knows of the load they push against, and what
/// it cannot know (on the gearbox-output scale, per motor).
struct MotorBalance {
  bool finite = false;                     ///< the row has every signal the balance needs
  ArmJoints joints = ArmJoints::Zero();    ///< rad, m
  ArmJoints applied = ArmJoints::Zero();   ///< the amplifiers' torque
  ArmJoints known = ArmJoints::Zero();     ///< fitted weight + offset + J a + b v - applied
  ArmJoints band = ArmJoints::Zero();      ///< each motor's Coulomb friction band
  ArmJoints sliding = ArmJoints::Zero();   ///< +-1 sliding that way, 0 maybe stuck
  ArmJoints friction = ArmJoints::Zero();  ///< the friction taken
  ArmJoints variance = ArmJoints::Zero();  ///< of known + friction
};

/// Motor signals to contact forces for one arm, over a whole recording (velocities and
/// accelerations come from the motor angles around each row).
class ArmForceEstimator {
 public:
  /// `uncertainty`: the calibration's standard deviation of each fitted value (0: exact).
  /// Throws std::invalid_argument for a grip depth of 0 or not finite, or a spread below 0.
  ArmForceEstimator(Arm arm, const MotorMechanics& mechanics, const MotorMechanics& uncertainty,
                    const raven::ArmKinematics& kinematics, GripLever grip = {});

  /// One estimate per row; `times` (s) never fall (std::invalid_argument naming the data row,
  /// from 1, otherwise) and match `rows`.
  std::vector<ForceEstimate> estimate(const std::vector<double>& times,
                                      const std::vector<recording::ArmSignals>& rows) const;

  /// Rows closer than this on either side are averaged into a row's motor speed (s), at most
  /// kWindowRows of them (a file whose clock stands still costs no more than one that runs).
  static constexpr double kSpeedWindow = 0.01;
  static constexpr std::size_t kWindowRows = 100;

 private:
  /// The torque the amplifier applied (gearbox-output scale): the DAC counts where logged, else
  /// Tau through the DAC's clip.
  ArmJoints appliedTorque(const recording::ArmSignals& row) const;
  /// Every row's balance, with which way each motor slides.
  std::vector<MotorBalance> balances(const std::vector<double>& times,
                                     const std::vector<recording::ArmSignals>& rows) const;
  MotorBalance balance(const recording::ArmSignals& row, const ArmJoints& speed,
                       const ArmJoints& acceleration) const;
  /// Each motor's friction and its variance, row after row.
  void addFriction(std::vector<MotorBalance>& rows) const;
  ForceEstimate estimateRow(const MotorBalance& b) const;
  /// The grip point's position Jacobian in the shoulder, elbow and insertion at `joints`.
  Eigen::Matrix3d tipJacobian(const ArmJoints& joints) const;

  Arm arm_;
  MotorMechanics mechanics_;
  MotorMechanics uncertainty_;
  raven::ArmKinematics kinematics_;
  GripLever grip_;
  DriveTrain drive_;
  DacConversion dac_;
  /// C^T diag(1 / gearbox): joint loads of torques on the gearbox-output scale.
  Eigen::Matrix<double, kJointCount, kJointCount> to_joints_;
};

}  // namespace twin
