#pragma once
// The benchmark's sections; each measures one part of the pipeline and adds rows to a Report.

#include <filesystem>

#include "report.hpp"

namespace bench {

/// What every section needs to know.
struct BenchSettings {
  int repeat = 3;               ///< repetitions of each timed run
  double scene_seconds = 30.0;  ///< simulated seconds of the moving peg-transfer scene per run
  std::filesystem::path shared_data;   ///< ../shared/data (may be absent)
  std::filesystem::path dense_models;  ///< the build's dense-collision models
  std::filesystem::path programs;      ///< the build directory (main job, twin node, micro bench)
};

/// Dynamic loop frequency: the moving peg-transfer scene (simplified vs dense collision,
/// free-running and paced), the Raven-II alone, AMBF's Raven-II.
void measureLoopFrequency(const BenchSettings& settings, Report& report);
/// AMBF's own description files (the Raven, puzzles, a cloth) against AMBF's figures on them.
void measureAmbfScenes(const BenchSettings& settings, Report& report);
/// Command rate and period jitter at 500 Hz and 1 kHz; virtual-gamepad-to-command latency.
void measureController(const BenchSettings& settings, Report& report);
/// The paper's 2arm inputs replayed on the twin in lock-step, as a multiple of real time.
void measureReplay(const BenchSettings& settings, Report& report);
/// The twin node's publish rate and command-to-state latency over loopback ROS.
void measureRosEdge(const BenchSettings& settings, Report& report);
/// Peak resident size of the main job and of the twin node.
void measureMemory(const BenchSettings& settings, Report& report);
/// The peg-transfer scene's loop frequency with the viewer window open against headless (needs a
/// display).
void measureViewer(const BenchSettings& settings, Report& report);
/// The main job's real-time factor with and without a video.
void measureVideo(const BenchSettings& settings, Report& report);
/// raven_sim from Python: a 1 ms step per call against C++, and N environments on threads.
void measurePython(const BenchSettings& settings, Report& report);
/// The Google Benchmark micro-benchmarks (IK, interpolation, a physics step).
void measureMicro(const BenchSettings& settings, Report& report);
/// Camera observations: frames per second of the peg-transfer scene's overview camera
/// (camera_cost.cpp).
void measureCameras(const BenchSettings& settings, Report& report);
/// A learner's snapshots: save and restore of a peg-transfer episode against a reset.
void measureSnapshots(const BenchSettings& settings, Report& report);
/// scripts/soak.sh's ten-minute run: RSS and step-time growth over a long session and batch.
void measureSoak(const BenchSettings& settings, Report& report);
/// raven_analyze forces: rows per second of the force estimate on a robot recording.
void measureForces(const BenchSettings& settings, Report& report);
/// Learning at full size: demonstrations, training and success of the state policy.
void measureTraining(const BenchSettings& settings, Report& report);
/// A policy's robustness: the image policy at the ranges' edges against the nominal scene.
void measurePolicyRobustness(const BenchSettings& settings, Report& report);

}  // namespace bench
