#pragma once
// How much recordings tell about the motors' fitted mechanics: per arm and motor, the Fisher
// information J^T J / sigma^2 of its values (twin::MotorMechanics::kNames),
// with J the sensitivity of that motor's logged signals (mpos, mvel, Tau at every row) found by
// finite differences of the setpoint replay, and sigma the encoder's quantisation noise (one
// count / sqrt(12) on mpos, its one-cycle difference on mvel, both through the gains on Tau).
// Rows count as independent, so the bound is optimistic; ratios between designs are what the
// active learning uses. Motors are taken as independent (block-diagonal information).

#include <Eigen/Core>
#include <array>

#include "analysis/actuator_signals.hpp"
#include "twin/motor_actuation.hpp"

namespace calibration {

/// The order of each motor's values in its block.
inline constexpr int kMechanicsValues = static_cast<int>(twin::MotorMechanics::kNames.size());
/// Whether motor `joint` has value `v` (kNames index): a face only on the jaws, a gravity error
/// only on the arm motors (shoulder, elbow, insertion); every other value on every motor.
bool motorHasValue(int joint, int v);
using InformationBlock = Eigen::Matrix<double, kMechanicsValues, kMechanicsValues>;

struct MechanicsInformation {
  raven::PerArm<std::array<InformationBlock, raven::kJointCount>> blocks;

  /// No information at all.
  static MechanicsInformation none();
  /// A prior from standard deviations (0: that value is not fitted, and stays out).
  static MechanicsInformation fromUncertainty(const twin::ArmsMechanics& sd);
  MechanicsInformation& operator+=(const MechanicsInformation& o);
  /// sqrt(diag(inverse)) per block over the values with information; 0 elsewhere.
  twin::ArmsMechanics standardDeviations() const;
  /// Sum over motors of log det of the block restricted to the values `sd` marks fitted:
  /// what a D-optimal design maximises.
  double logDet(const twin::ArmsMechanics& fitted) const;
};

/// The encoders' quantisation noise on mpos, mvel and Tau of `arm`, in the logged units.
std::array<raven::ArmJoints, 3> quantisationNoise(raven::Arm arm);

/// The information one recording (its setpoints replayed from its start) carries about
/// `mechanics`.
MechanicsInformation informationOf(const twin::ArmsMechanics& mechanics,
                                   const analysis::ActuatorTrace& recording);

}  // namespace calibration
