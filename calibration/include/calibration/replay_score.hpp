#pragma once
// How a twin replays a set of physical recordings of one input file, end to end: for each
// physical trial the twin starts where that trial began and replays the inputs through the
// controller; its joints (the paper's j_P and j_V figures) and its actuator signals (mpos, mvel,
// Tau, dac_vals) are compared with that trial, relative to the robot's own trial-to-trial spread.

#include <vector>

#include "analysis/actuator_signals.hpp"
#include "calibration/fidelity.hpp"
#include "calibration/twin_replay.hpp"

namespace calibration {

struct ReplayScore {
  /// Twin vs its own physical trial, averaged over trials; [0] as recorded, [1] with each
  /// trial's first row removed: the eight joint figures.
  std::array<Figures, 2> twin{};
  std::array<Figures, 2> robot{};  ///< T_PP, the same two ways
  analysis::ActuatorFidelity actuators;
  std::vector<recording::RsRecording> replays;  ///< one per physical trial
  /// How many of the eight joint figures are within the robot's own.
  int figuresWithin() const;
};

/// Replays `setup` (its `start` is replaced per trial) against `physical`: two or more trials of
/// the physical robot replaying those inputs, each with its actuator signals (throws
/// std::invalid_argument naming a trial without).
ReplayScore scoreReplays(ReplaySetup setup, const std::vector<analysis::Trial>& physical);

}  // namespace calibration
