#pragma once
// Active learning for the actuation fit: candidate excitation motions as gamepad inputs (a ci
// file the controller replays on the twin or the real robot, so every command passes the
// controller's velocity caps and joint limits), and the choice of the one whose recording would
// most reduce the uncertainty of the fitted mechanics (D-optimal: the largest log det of the
// prior information plus the candidate's).

#include <random>
#include <vector>

#include "calibration/mechanics_information.hpp"
#include "calibration/twin_replay.hpp"
#include "recording/gamepad_state.hpp"
#include "twin/calibration_profile.hpp"

namespace calibration {

/// How candidate motions are drawn.
struct ExcitationOptions {
  double seconds = 20.0;     ///< length of each candidate
  double iteration = 0.022;  ///< s per ci row (the recording controller's manual loop)
};

/// A random excitation: segments of M2 (both arms' positions and jaws), M1-left and M1-right
/// (that arm's roll and wrist, and its position), each driving a random subset of the sticks,
/// bumpers and triggers with zero-mean sines of random amplitude, frequency and phase.
std::vector<recording::GamepadState> randomExcitation(std::mt19937_64& random,
                                                      const ExcitationOptions& options);

/// One scored candidate.
struct Candidate {
  std::vector<recording::GamepadState> inputs;
  analysis::ActuatorTrace trace;  ///< its replay on the twin
  MechanicsInformation information;
  double log_det = 0.0;       ///< of prior + this candidate's information
  bool within_limits = true;  ///< no joint came within 1 % of its range of a limit
};

/// Replays `inputs` on a twin with `profile`'s mechanics (controller settings from `setup`) and
/// scores what its recording would tell, on top of `prior`.
Candidate scoreCandidate(const ReplaySetup& setup, const twin::CalibrationProfile& profile,
                         const MechanicsInformation& prior,
                         std::vector<recording::GamepadState> inputs);

/// The expected standard deviations after adding `candidate` to `prior`.
twin::ArmsMechanics expectedUncertainty(const MechanicsInformation& prior,
                                        const Candidate& candidate);

/// Mean over the fitted values of 1 - (sd after / sd before): the expected reduction.
double meanReduction(const twin::ArmsMechanics& before, const twin::ArmsMechanics& after);

}  // namespace calibration
