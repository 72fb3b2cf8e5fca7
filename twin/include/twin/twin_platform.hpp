#pragma once
// The in-process twin: our Raven-II (or AMBF's) in an ambf_like World, behind RavenPlatform,
// on the simulated or the wall clock.

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>

#include "ambf_like/scene_loader.hpp"
#include "ambf_like/world.hpp"
#include "bridge/raven_platform.hpp"
#include "bridge/wall_pacer.hpp"
#include "twin/actuation.hpp"
#include "twin/drive_train.hpp"
#include "twin/motor_actuation.hpp"
#include "twin/raven_core.hpp"
#include "twin/twin_arms.hpp"
#include "twin/vocabulary.hpp"

namespace twin {

/// What a twin is built from.
struct TwinOptions {
  /// A launch file with the robot (and perhaps a scene); default: our Raven-II alone.
  std::filesystem::path launch_file = raven::modelDirectory() / "raven2" / "launch.yaml";
  /// How strictly the model files are read (AMBF's own Raven-II loads with warnings: two of
  /// its meshes are missing upstream).
  ambf_like::LoadOptions load;
  /// Applied to the loaded scene before the World is built (randomised batches vary friction,
  /// softness and start poses this way).
  std::function<void(ambf_like::SceneSpec&)> adjust_scene;
  twin::ArmBindings bindings = twin::ArmBindings::ourRaven();
  /// "physical" (our model) or "ambf" (AMBF's blender-raven2.yaml), or a profile file.
  std::string profile = "physical";
  ClockKind clock = ClockKind::Simulated;
  /// Set: the Raven-II's motor-level actuation with these mechanics (raven_calibrate fits
  /// them); unset: the twin's ideal servos.
  std::optional<ArmsMechanics> motors;
  ServoLimits limits;
  /// Called after every World step, on the thread that steps it (a video's capture).
  std::function<void(const ambf_like::World&)> after_step;
};

/// A simulated Raven-II, one robot cycle per World step.
class TwinPlatform final : public RavenPlatform {
 public:
  /// Throws common::LoadError for bad model or profile files, std::out_of_range for bindings
  /// that name joints the model lacks.
  explicit TwinPlatform(const TwinOptions& options = {});

  /// Enabling after a fault powers the amplifiers again.
  CommandResult send(const PlatformCommand& command) override;
  OperatingStatus operatingStatus() const override { return core_.status(); }
  JointSample measuredJs(Arm arm) const override;
  JointSample setpointJs(Arm arm) const override;
  PoseSample measuredCp(Arm arm) const override;
  /// Contact forces of the jaws in the last physics step (GrasperForces).
  std::optional<GrasperForces> measuredCf(Arm arm) const override;
  PoseSample setpointCp(Arm arm) const override;
  std::optional<RavenStateSnapshot> ravenState() const override;
  ClockKind clockKind() const override { return clock_; }
  double now() const override { return core_.time(); }
  void advance(double seconds) override;

  /// Puts `arm` where a recording began (its motors, encoders and control state); its joint
  /// setpoint stays where it is (send move_jp to the recorded one first).
  void place(Arm arm, const ArmStart& start);

  /// The simulation, for scenes that need more than the arms (rings, contacts).
  ambf_like::World& world() { return world_; }
  const ambf_like::World& world() const { return world_; }
  const RavenCore& core() const { return core_; }
  /// The arm layer over the simulation (joint bindings, jaw stops).
  const TwinArms& arms() const { return arms_; }

  /// The twin's state between cycles: its World (World::saveState says what that holds and
  /// the caches it rebuilds), the actuation's motors and controllers, the command layer and the
  /// clock. Throws std::logic_error on the wall clock (its pacing is not state).
  struct State;
  std::shared_ptr<const State> saveState();
  /// Puts the twin back to `state`, which only this twin saved (else its world throws
  /// std::invalid_argument before anything changes).
  void restoreState(const State& state);

 private:
  void runCycle();
  ArmPair measuredPositions() const;

  ambf_like::LoadedScene scene_;
  ambf_like::MeshLibrary meshes_;
  ambf_like::World world_;
  twin::TwinArms arms_;
  DriveTrain drive_;
  std::unique_ptr<Actuation> actuation_;
  raven::PerArm<ActuatorReadings> readings_;
  ArmPair previous_position_;
  RavenCore core_;
  ClockKind clock_;
  std::function<void(const ambf_like::World&)> after_step_;
  WallPacer pacer_;
  double requested_ = 0.0;  ///< platform time asked for so far
};

}  // namespace twin
