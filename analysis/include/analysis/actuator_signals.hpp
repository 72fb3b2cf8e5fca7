#pragma once
// What a Raven-II recording says below the joints, per arm and row in SI units
// (recording::ArmSignals), and how far two platforms' actuator signals sit apart relative to the
// robot's own trial-to-trial spread, compared in the units the robot logs them in.

#include <array>
#include <optional>
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
/// One row's signal of one arm in the logged unit.
raven::ArmJoints logged(const recording::ArmSignals& row, ActuatorSignal s);

/// One recording below the joints.
struct ActuatorTrace {
  std::string name;
  std::vector<double> time;                                ///< s from the first row
  raven::PerArm<std::vector<recording::ArmSignals>> arms;  ///< per arm, one entry per row
  std::size_t rows() const { return time.size(); }
};

/// Reads the actuator columns of an rs recording of the physical robot or our twin; throws
/// recording::RecordingError naming the file and the missing column.
ActuatorTrace actuatorTrace(const recording::RsRecording& rs);
/// The recording's trace when it logs actuator signals: every column there, every value a
/// number, the motor angles not all zero (AMBF's recordings log none).
std::optional<ActuatorTrace> loggedActuatorTrace(const recording::RsRecording& rs);

/// Per signal (kActuatorSignals order) and arm, a value per joint.
using SignalJoints = std::array<raven::PerArm<raven::ArmJoints>, 4>;
SignalJoints zeroSignals();

/// Mean |a - b| of one signal per arm and joint over the rows both have (logged units).
raven::PerArm<raven::ArmJoints> meanAbsoluteDifference(const ActuatorTrace& a,
                                                       const ActuatorTrace& b, ActuatorSignal s);
/// The median over the arms' joints the robot moves (spread > 0) of value / spread.
double medianRatio(const raven::PerArm<raven::ArmJoints>& value,
                   const raven::PerArm<raven::ArmJoints>& spread);

/// Per signal, arm and joint: the twin's difference from the physical trials over the robot's
/// own spread (mean over trial pairs of mean |physical_i - physical_j|).
struct ActuatorFidelity {
  /// twin[s][arm](j): mean over the trials of |twin - physical|; one twin trace per physical
  /// trace (a replay from that trial's start), or one for all.
  SignalJoints twin = zeroSignals(), spread = zeroSignals();
  /// medianRatio(twin, spread) per signal.
  std::array<double, 4> median_ratio{};
};
/// The spread is that of `spread_from` (two or more trials; empty: `physical`), so a trial
/// held out of a fit can be scored against the spread of the trials it was fitted on.
ActuatorFidelity actuatorFidelity(const std::vector<ActuatorTrace>& twin,
                                  const std::vector<ActuatorTrace>& physical,
                                  const std::vector<ActuatorTrace>& spread_from = {});

}  // namespace analysis
