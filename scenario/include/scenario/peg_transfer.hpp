#pragma once
// The peg-transfer scenario, the project's main job: both arms move the six soft rings from the
// start row to the target row, driven through the same controller path a gamepad uses
// (DualPlatformController: velocity caps, wrist-locked IK), optionally recording the paper's rs
// file. The job sees only a RavenPlatform and a ScenePerception, so it runs on the in-process
// twin (runPegTransfer) and on any platform with a perception (runPegTransferOn: the twin node
// over ROS, or the physical robot with a tracker).

#include <array>
#include <atomic>
#include <cstdint>
#include <filesystem>

#include "bridge/raven_platform.hpp"
#include "bridge/scene_perception.hpp"
#include "scenario/arm_routine.hpp"
#include "scenario/peg_transfer_result.hpp"
#include "scenario/run_progress.hpp"
#include "scenario/scene_variation.hpp"
#include "twin/twin_platform.hpp"

namespace scenario {

/// How to run the scenario.
struct PegTransferOptions {
  std::uint64_t seed = 0;
  /// Draw the scene from `seed` (scene_variation.hpp's ranges); else the nominal scene.
  bool randomize = false;
  /// What a randomised scene is drawn from.
  VariationRanges ranges;
  AssistMode assist = AssistMode::Off;
  /// How far (m) the closed jaws reach into a ring's wall (ArmRoutine).
  double squeeze = ArmRoutine::kDefaultSqueeze;
  /// The Raven-II's motor-level actuation (the shipped calibration), or ideal joint servos.
  common::ActuationKind actuation = common::ActuationKind::Motors;
  /// The motors' calibration profile (raven_calibrate's YAML); empty: the shipped one.
  std::filesystem::path calibration;
  /// The scene's launch file; empty: raven_description's peg_transfer (the benchmarks pass the
  /// dense-collision variant).
  std::filesystem::path launch_file;
  /// Simulated: as fast as the CPU allows; Wall: paced to real time (1 kHz physics).
  bridge::ClockKind clock = bridge::ClockKind::Simulated;
  /// Resting rings sleep (ambf_like's SoftBodySleep); false steps every ring at every step.
  bool soft_body_sleep = true;
  /// Writes the rs recording here (one row per manual-loop iteration); empty: none.
  std::filesystem::path rs_file;
  /// Without an rs_file: writes peg_transfer_seed<N>_rs.csv into this folder (a batch's runs).
  std::filesystem::path rs_folder;
  /// When it turns true (a signal handler's flag) the run stops after the current iteration and
  /// says so (`stopped`); a batch starts no further run.
  const std::atomic<bool>* stop = nullptr;

  bool stopRequested() const { return stop != nullptr && stop->load(); }
  /// Simulated seconds after which the run stops, whatever is left undone.
  double time_limit = 240.0;
  /// Simulated seconds the rings settle after the last release before they are judged.
  double settle_time = 1.0;
  /// Called after every manual-loop iteration.
  ProgressCallback progress;
  /// Shown the world before the first move, after every manual-loop iteration (settling too)
  /// and once the rings are judged: the viewer's hook (in process only).
  WorldObserver observe;
};

/// Runs the scenario once on the in-process twin. Throws common::LoadError if the scene's files
/// are bad.
PegTransferResult runPegTransfer(const PegTransferOptions& options);

/// Runs the scenario once on `platform` (enabled and homed here), seeing the rings through
/// `scene`. The options that build a twin (seed variation, assist, actuation, scene file, sleep,
/// observer) are the platform's business and not read; the result's variation is nominal.
PegTransferResult runPegTransferOn(bridge::RavenPlatform& platform, bridge::ScenePerception& scene,
                                   const PegTransferOptions& options);

/// The twin of a run: its scene (the shipped one or `launch_file`) with `variation` applied,
/// sleep, the assist's sensors and the actuation as the options say.
twin::TwinOptions pegTransferTwin(const PegTransferOptions& options,
                                  const SceneVariation& variation);
/// The scripted operators of both arms (left first), each with its arm's jobs.
raven::PerArm<ArmRoutine> pegTransferOperators(const PegLayout& layout, double squeeze);

}  // namespace scenario
