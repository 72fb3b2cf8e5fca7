#pragma once
// What a Raven-II recording says below the joints, per arm in SI units (motor rad, rad/s, N m,
// DAC counts; raven2-actuation.md §1), and how far two platforms' actuator signals sit apart
// relative to the robot's own trial-to-trial spread.

#include <array>
#include <string>
#include <vector>

#include "raven/arm.hpp"
#include "recording/recording_io.hpp"

namespace analysis {

/// The actuator columns the robot logs: mpos, mvel, Tau, dac_vals.
enum class ActuatorSignal { MotorPosition, MotorVelocity, Torque, Dac };
inline constexpr std::array<ActuatorSignal, 4> kActuatorSignals{
    ActuatorSignal::MotorPosition, ActuatorSignal::MotorVelocity, ActuatorSignal::Torque,
    ActuatorSignal::Dac};
/// "mpos", "mvel", "Tau", "dac_vals": the recorder's column names.
const char* columnName(ActuatorSignal s);
/// The logged unit: "deg", "deg/s", "N m", "counts".
const char* loggedUnit(ActuatorSignal s);

/// One arm of one recording's rows, in SI (raven::ArmJoints order).
struct ArmTrace {
  std::vector<raven::ArmJoints> joints, joint_setpoint;  ///< jpos, jpos_d (rad, m)
  std::vector<raven::ArmJoints> motor, motor_velocity;   ///< mpos, mvel (rad, rad/s)
  std::vector<raven::ArmJoints> motor_setpoint, torque;  ///< mpos_d (rad), Tau (N m)
  std::vector<raven::ArmJoints> dac;                     ///< counts
  /// The signal in the logged unit (degrees for motor angles), for comparing as the robot logs.
  const std::vector<raven::ArmJoints>& of(ActuatorSignal s) const;
};

/// One recording below the joints.
struct ActuatorTrace {
  std::string name;
  std::vector<double> time;  ///< s from the first row
  std::array<ArmTrace, 2> arms;
  std::size_t rows() const { return time.size(); }
};

/// Reads the actuator columns of an rs recording of the physical robot or our twin; throws
/// recording::RecordingError naming the file and the missing column.
ActuatorTrace actuatorTrace(const recording::RsRecording& rs);

/// Mean |a - b| of one signal per arm and joint over the rows both have (logged units).
std::array<raven::ArmJoints, 2> meanAbsoluteDifference(const ActuatorTrace& a,
                                                       const ActuatorTrace& b, ActuatorSignal s);

/// Per signal, arm and joint: the twin's difference from the physical trials over the robot's
/// own spread (mean over trial pairs of mean |physical_i - physical_j|).
struct ActuatorFidelity {
  /// twin[s][arm](j): mean over the trials of |twin - physical|; one twin trace per physical
  /// trace (a replay from that trial's start), or one for all.
  std::array<std::array<raven::ArmJoints, 2>, 4> twin = zeros(), spread = zeros();
  /// ratio twin / spread, median over the arms' joints that move (spread > 0).
  std::array<double, 4> median_ratio{};

 private:
  static std::array<std::array<raven::ArmJoints, 2>, 4> zeros() {
    std::array<std::array<raven::ArmJoints, 2>, 4> z;
    for (auto& signal : z) signal.fill(raven::ArmJoints::Zero());
    return z;
  }
};
/// The spread is that of `spread_from` (two or more trials; empty: `physical`), so a trial
/// held out of a fit can be scored against the spread of the trials it was fitted on.
ActuatorFidelity actuatorFidelity(const std::vector<ActuatorTrace>& twin,
                                  const std::vector<ActuatorTrace>& physical,
                                  const std::vector<ActuatorTrace>& spread_from = {});

}  // namespace analysis
