#pragma once
// Fits the mechanics behind the Raven-II's motors (twin::MotorMechanics: inertia, Coulomb
// friction, its load-dependent part and its asymmetry, viscous friction, the gravity
// compensation's error) to physical recordings: each recording's joint setpoints drive the
// motor-level model from the state the robot was in (replaySetpoints), and a bounded
// derivative-free optimiser (NLopt's BOBYQA) brings its motor angles, velocities and torques to
// the robot's, each over the robot's own trial-to-trial spread.

#include <functional>
#include <string>
#include <vector>

#include "analysis/actuator_signals.hpp"
#include "twin/motor_actuation.hpp"

namespace calibration {

/// One fitted quantity of one motor: its field, bounds and scale.
struct MechanicsParameter {
  std::size_t field = 0;  ///< index into twin::MotorMechanics::kNames
  double lower = 0.0, upper = 1.0;
  bool log_scale = false;
};
/// The quantities fitted for joint `joint`: those it has (motorHasValue), with their bounds.
std::vector<MechanicsParameter> mechanicsParameters(int joint);

/// The values a fit starts from: catalogue rotor inertias through the gearboxes, the friction
/// CSLDepend/raven2_sim fitted on its own robot (raven2-actuation.md §5), exact gravity.
twin::ArmsMechanics startingMechanics();

/// A broad prior for mechanics nobody has fitted yet: half of each value, 0.2 for the load
/// friction and (arm motors only) the gravity error, half the Coulomb friction for its offset.
twin::ArmsMechanics broadUncertainty(const twin::ArmsMechanics& mechanics);

/// Per arm and joint, how far the model's signals sit from the recordings: the mean over mpos,
/// mvel and Tau of mean |model - recording| over the recordings' spread (`spread`: per signal
/// and arm, analysis::ActuatorFidelity's).
struct MechanicsScore {
  raven::PerArm<raven::ArmJoints> joint{raven::ArmJoints::Zero(), raven::ArmJoints::Zero()};
  double total() const;
};
MechanicsScore scoreMechanics(const twin::ArmsMechanics& mechanics,
                              const std::vector<analysis::ActuatorTrace>& recordings,
                              const analysis::ActuatorFidelity& spread);

struct ActuationFitOptions {
  int evaluations_per_joint = 60;
  int sweeps = 2;  ///< passes over the joints (the tool motors follow the insertion's)
  /// The recordings repeat one motion (two or more): differences count over the robot's own
  /// trial-to-trial spread. Otherwise (different motions, e.g. proposed excitations) over the
  /// encoders' quantisation noise.
  bool same_motion = true;
  /// Which of twin::MotorMechanics::kNames are fitted (indices); empty: every one.
  std::vector<std::size_t> fields;
};

struct ActuationFitResult {
  twin::ArmsMechanics mechanics;
  MechanicsScore score;
  int evaluations = 0;
};

/// Fits every arm's motors to `train`, one motor at a time, starting from `initial`. `progress` (if
/// set) gets a line per fitted motor.
ActuationFitResult fitActuation(const std::vector<analysis::ActuatorTrace>& train,
                                const twin::ArmsMechanics& initial,
                                const ActuationFitOptions& options,
                                const std::function<void(const std::string&)>& progress = {});

}  // namespace calibration
