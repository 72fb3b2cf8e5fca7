#pragma once
// The peg transfer as a learning environment (Gymnasium's reset/step convention): one step is
// one manual-loop iteration of the controller a gamepad uses (the arms reach the action's
// targets under the velocity caps) or a fixed period (they follow it for exactly that long);
// the action is joint targets, joint deltas, tool-tip displacements with the jaws (env_action)
// or a pad reading; the observation is the robot, the rings and the grasp forces; the scripted
// operator of the main job is there as the expert.

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "common/actuation_kind.hpp"
#include "scenario/arm_routine.hpp"
#include "scenario/env_action.hpp"
#include "scenario/observation_layout.hpp"
#include "scenario/peg_layout.hpp"
#include "scenario/scene_variation.hpp"
#include "scenario/scripted_session.hpp"
#include "twin/world_perception.hpp"

namespace scenario {

/// How long a step lasts.
enum class EnvControl {
  /// Until the arms' setpoints reach the action's targets under the caps (a manual iteration),
  /// then until the arms arrive or stop (arrival()).
  Waypoint,
  Period  ///< exactly PegTransferEnvOptions::period: a move cut short there, or held after
};

/// How the environment's episodes run.
struct PegTransferEnvOptions {
  EnvAction action = EnvAction::Joints;
  EnvControl control = EnvControl::Waypoint;
  double period = 0.05;  ///< s per step under EnvControl::Period (whole command periods)
  /// Draw each episode's scene from its reset seed (scene_variation.hpp's ranges); else the
  /// nominal scene every time.
  bool randomize = false;
  /// What a randomised scene is drawn from.
  VariationRanges ranges;
  /// Simulated seconds after which an episode is truncated.
  double time_limit = 240.0;
  /// The expert's squeeze (ArmRoutine).
  double squeeze = ArmRoutine::kDefaultSqueeze;
  /// The scene; empty: the shipped peg_transfer.
  std::filesystem::path launch_file;
  /// The Raven-II's motor-level actuation (the shipped calibration), or ideal joint servos.
  common::ActuationKind actuation = common::ActuationKind::Motors;
};

/// What one step gives back.
struct PegTransferStep {
  Eigen::VectorXd observation;
  /// Rings placed now minus rings placed before the step: +1 as a ring comes to rest threaded
  /// on its target post, -1 if one leaves it.
  double reward = 0.0;
  bool terminated = false;  ///< all six rest on their target posts
  bool truncated = false;   ///< the time limit passed first, the robot faulted, or the world failed
  /// The robot e-stopped (FAULT: an amplifier past its overdrive threshold, a guard tripped):
  /// it refuses every command until enabled again, so the episode is truncated here rather than
  /// run on, refused, to its time limit.
  bool faulted = false;
  /// Why the world failed in this step (its guard: ambf_like::SimulationDiverged), or empty.
  /// Then the episode is truncated, the observation is the last good one and the reward 0;
  /// step() refuses to go on until reset().
  std::string failure;
  int placed = 0;           ///< rings resting on their target posts
  std::size_t refused = 0;  ///< commands the twin refused during the step
};

/// One episode at a time of the nominal or a randomised peg transfer on the in-process twin,
/// on the simulated clock (deterministic: the same seed and actions give the same episode).
class PegTransferEnv {
 public:
  /// The observation's size; what sits where: scenario/observation_layout.hpp.
  static constexpr int kObservationSize = observation::kSize;

  explicit PegTransferEnv(PegTransferEnvOptions options = {});
  ~PegTransferEnv();

  /// Builds the episode's twin (from `seed` when randomising), enables and homes it, and returns
  /// the first observation. Throws common::LoadError for bad scene files.
  Eigen::VectorXd reset(std::uint64_t seed);
  /// One step of the options' action (clipped to its bounds, its targets clamped to the joint
  /// limits, reached under the caps). Needs reset(). Throws std::invalid_argument for an action
  /// of the wrong size or with a value that is not finite.
  PegTransferStep step(const Eigen::VectorXd& action);
  /// One manual-loop iteration from a pad reading (the paper's mapping, as a live pad).
  PegTransferStep step(const recording::GamepadState& pad);
  /// What the main job's scripted operator would command next, as an action of the options'
  /// kind (call once per step: it keeps its own progress); the targets held once it is done.
  /// `from_state`: the operator first takes up the task from the state reached
  /// (ArmRoutine::resume), for steps someone else decided (DAgger's labels).
  Eigen::VectorXd expertAction(bool from_state = false);
  /// Per arm (left first), how many of its jobs the expert has finished, placed or given up
  /// (ArmRoutine::finished): 0 at reset, 3 once it is done.
  std::array<int, 2> expertJobsFinished() const;

  /// The episode's state between steps: the twin's (TwinPlatform::saveState), the controller's,
  /// the expert's progress and the episode's count. The same actions after a restore give the
  /// same observations, bit for bit. Throws std::logic_error before reset() or after the world
  /// failed.
  struct State;
  std::shared_ptr<const State> saveState();
  /// Puts the episode back to `state`, saved by this environment in this episode (else
  /// std::invalid_argument: reset() builds a new world).
  void restoreState(const State& state);

  int actionSize() const { return scenario::actionSize(options_.action); }
  /// An action's bounds.
  Eigen::VectorXd actionLow() const;
  Eigen::VectorXd actionHigh() const;
  double time() const;
  int placed() const { return placed_; }
  /// Both arms' tool points (rows, m) in the scene's world frame, the rings' frame, for 14 joint
  /// values (left arm first), as the expert's kinematics place them; the observation's tool
  /// poses are the robot's own report, in its frames.
  static Eigen::Matrix<double, 2, 3, Eigen::RowMajor> toolPoints(
      const Eigen::Matrix<double, 14, 1>& joints);
  /// What the episode's scene was drawn as (nominal unless randomising), as reset() drew it.
  const SceneVariation& variation() const { return variation_; }
  /// The last step's (or reset's, or restored) observation.
  const Eigen::VectorXd& observation() const { return last_observation_; }
  twin::TwinPlatform& twin();

 private:
  /// Runs one step's commands (`run` returns how many the twin refused) and observes; a world
  /// that fails in them truncates the episode.
  PegTransferStep guardedStep(const std::function<std::size_t()>& run);
  PegTransferStep finishStep(std::size_t refused);
  Eigen::VectorXd observe() const;
  int countPlaced() const;
  ScriptedSession& session();

  PegTransferEnvOptions options_;
  raven::PlatformProfile profile_;  ///< the controller's (the physical one), read once
  raven::PerArm<raven::ArmKinematics> kinematics_;
  PegLayout layout_;
  std::unique_ptr<ScriptedSession> session_;
  std::optional<raven::PerArm<ArmRoutine>> expert_;
  std::array<const ambf_like::SoftBody*, 6> rings_{};
  std::unique_ptr<twin::WorldPerception> scene_;  ///< what the expert and the judge see
  int placed_ = 0;
  std::uint64_t episode_ = 0;  ///< resets so far (a saved state names its episode)
  Eigen::VectorXd last_observation_;
  std::string failure_;  ///< why the episode's world failed, or empty
  SceneVariation variation_;
};

}  // namespace scenario
