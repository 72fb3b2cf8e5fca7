#pragma once
// What one peg-transfer run did: each peg's outcome, the run's timing, and its JSON line.

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "common/actuation_kind.hpp"
#include "raven/arm.hpp"
#include "scenario/run_timing.hpp"
#include "scenario/scene_variation.hpp"

namespace scenario {

/// Whether the grasp assist may pin a touched ring to the jaws (grasp_assist.hpp).
enum class AssistMode { Off, Contact };

std::string_view assistName(AssistMode mode);

/// One ring's transfer, as the run's ScenePerception showed it.
struct RingOutcome {
  std::string ring;  ///< its soft body's name in the scene (ring1..ring6)
  raven::Arm arm = raven::Arm::Left;
  Eigen::Vector2d from = Eigen::Vector2d::Zero(), to = Eigen::Vector2d::Zero();
  bool grasped = false;  ///< the ring left the board (its bottom 5 mm above it)
  double lift = 0.0;     ///< the highest its bottom rose above the board (m)
  int regrasps = 0;      ///< times the operator opened and grasped it again (ArmRoutine)
  /// Each jaw's median normal force on it while carried (N; zeros if it never was).
  std::array<double, 2> carried_squeeze{0.0, 0.0};
  bool placed = false;  ///< at the end: resting on its target post
  bool lost = false;    ///< a non-finite pose, volume off by more than 20 %, or under the board
  std::string loss;     ///< why it counts as lost
  /// The perception reported its volume (a simulation does; AMBF's topics and a tracker do not).
  bool volume_seen = false;
  double min_volume_ratio = 1.0, max_volume_ratio = 1.0;  ///< volume / rest volume, extremes
  Eigen::Vector3d final_centre = Eigen::Vector3d::Zero();
  double miss = 0.0;  ///< final centre to the target post's axis, horizontally (m)
};

/// One run of the scenario.
struct PegTransferResult {
  SceneVariation variation;
  AssistMode assist = AssistMode::Off;
  common::ActuationKind actuation = common::ActuationKind::Motors;
  std::array<RingOutcome, 6> rings;
  bool timed_out = false;  ///< the simulated time limit ended it
  bool stopped = false;    ///< asked to stop (PegTransferOptions::stop) before it was done
  /// Why the run failed (the world's guard: ambf_like::SimulationDiverged), or empty. A failed
  /// run's rings have no outcome: nothing it measured after the world blew up is a result.
  std::string failure;
  RunTiming timing;
  std::size_t iterations = 0;  ///< manual-loop iterations
  std::size_t grasps = 0;      ///< grasps the assist made
  std::size_t refused = 0;     ///< commands the platform refused
  std::filesystem::path rs_file;
  std::size_t rs_rows = 0;

  std::size_t placed() const;
  std::size_t lost() const;
  std::size_t regrasps() const;
  bool allPlaced() const { return failure.empty() && placed() == rings.size(); }
  bool failed() const { return !failure.empty(); }
  /// One JSON object (a JSON-lines row).
  nlohmann::json json() const;
};

}  // namespace scenario
