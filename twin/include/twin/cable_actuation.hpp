#pragma once
// THE PHYSICAL STAND-IN: a model of the cable-driven Raven-II's actuation (motor-side PD at
// 1 kHz with the robot's gains, rotor inertia through the transmission, a compliant cable,
// encoder quantisation, optional noise) that drives the twin's joints. It stands in for hardware
// this project does not have; it is not a measurement of the robot.

#include <Eigen/Core>
#include <array>
#include <filesystem>
#include <random>

#include "twin/actuation.hpp"
#include "twin/drive_train.hpp"
#include "twin/twin_arms.hpp"
#include "twin/vocabulary.hpp"

namespace twin {

/// The stand-in's parameters (twin/config/physical_stand_in.yaml says where each comes from).
/// Joint order of raven::ArmJoints; "joint units" are rad, or m for the insertion.
struct CableActuationParams {
  raven::ArmJoints kp = raven::ArmJoints::Zero();  ///< motor torque per motor rad (N m / rad)
  raven::ArmJoints kd = raven::ArmJoints::Zero();  ///< N m s / rad at the motor
  /// The current clipping of the amplifiers, as a motor torque (N m).
  raven::ArmJoints max_motor_torque = raven::ArmJoints::Constant(1.0);
  raven::ArmJoints rotor_inertia = raven::ArmJoints::Zero();  ///< kg m^2 at the motor
  raven::ArmJoints friction = raven::ArmJoints::Zero();       ///< viscous, joint units at the joint
  raven::ArmJoints link_inertia = raven::ArmJoints::Zero();   ///< kg m^2 (kg: insertion)
  raven::ArmJoints cable_mode_hz = raven::ArmJoints::Constant(60.0);  ///< link on its cable
  double cable_damping_ratio = 0.1;
  double velocity_filter_hz = 100.0;  ///< the firmware's velocity low-pass
  double encoder_noise_counts = 0.0;  ///< standard deviation; 0 = exact quantisation
  unsigned seed = 1;

  /// Throws common::LoadError naming the file and key.
  static CableActuationParams load(const std::filesystem::path& file);
  /// twin/config/physical_stand_in.yaml.
  static CableActuationParams physicalStandIn();
};

/// Drives the twin's position servos to where the modelled links are, and reads the modelled
/// motor encoders the way the robot does (joint = motor / transmission).
class CableActuation final : public Actuation {
 public:
  /// Starts at rest at the arms' current joints.
  CableActuation(twin::TwinArms& arms, DriveTrain drive, const CableActuationParams& params,
                 double cycle);
  void drive(raven::Arm arm, const raven::ArmJoints& setpoint,
             const raven::ArmJoints& setpoint_velocity) override;
  ActuatorReadings read(raven::Arm arm) const override { return readings_[index(arm)]; }

 private:
  /// Motor angle and speed, link position and speed, in joint units.
  using JointState = Eigen::Vector4d;
  /// x(k+1) = phi x(k) + gamma u: the plant over one cycle with the motor torque held.
  struct Discrete {
    Eigen::Matrix4d phi;
    Eigen::Vector4d gamma;
  };
  static std::size_t index(raven::Arm arm) { return static_cast<std::size_t>(raven::index(arm)); }
  void measure(raven::Arm arm);

  twin::TwinArms& arms_;
  DriveTrain drive_;
  CableActuationParams params_;
  double cycle_;
  double velocity_alpha_;
  std::array<Discrete, raven::kJointCount> plant_;
  std::array<std::array<JointState, raven::kJointCount>, 2> state_;
  std::array<raven::ArmJoints, 2> motor_torque_;
  std::array<ActuatorReadings, 2> readings_;
  std::mt19937_64 random_;
};

}  // namespace twin
