#include "twin/twin_platform.hpp"

#include <cmath>
#include <stdexcept>

#include "raven_state_builder.hpp"
#include "twin/grasp_forces.hpp"
#include "twin/ideal_actuation.hpp"

namespace twin {

namespace {

raven::PlatformProfile loadProfile(const std::string& name_or_file) {
  if (name_or_file == "physical" || name_or_file == "ambf") {
    return raven::builtinProfile(name_or_file);
  }
  return raven::loadPlatformProfile(name_or_file);
}

ambf_like::WorldOptions worldOptions(const ServoLimits& limits) {
  ambf_like::WorldOptions options;
  options.step_size = limits.cycle;
  return options;
}

std::unique_ptr<Actuation> makeActuation(twin::TwinArms& arms, ambf_like::World& world,
                                         const DriveTrain& drive, const TwinOptions& options) {
  if (options.motors) {
    return std::make_unique<MotorActuation>(arms, world, drive, *options.motors,
                                            options.limits.cycle);
  }
  return std::make_unique<IdealActuation>(arms, drive);
}

ambf_like::LoadedScene loadScene(const TwinOptions& options) {
  ambf_like::LoadedScene scene = ambf_like::loadLaunchFile(options.launch_file, {}, options.load);
  if (options.adjust_scene) options.adjust_scene(scene.spec);
  // The motors drive an arm through its joints only where the arm is one articulation (one
  // integrator for links and rotors): a scene kept in maximal coordinates gets them where it can.
  if (options.motors && scene.spec.world.articulation == ambf_like::Articulation::Maximal) {
    scene.spec.world.articulation = ambf_like::Articulation::Automatic;
  }
  return scene;
}

raven::PerArm<ActuatorReadings> readAll(const Actuation& actuation) {
  return {actuation.read(Arm::Left), actuation.read(Arm::Right)};
}

}  // namespace

TwinPlatform::TwinPlatform(const TwinOptions& options)
    : scene_(loadScene(options)),
      world_(scene_.spec, meshes_, worldOptions(options.limits)),
      arms_(world_, options.bindings),
      drive_(DriveTrain::raven2()),
      actuation_(makeActuation(arms_, world_, drive_, options)),
      readings_(readAll(*actuation_)),
      previous_position_{readings_[0].position, readings_[1].position},
      core_(loadProfile(options.profile), options.limits, measuredPositions()),
      clock_(options.clock),
      after_step_(options.after_step) {}

CommandResult TwinPlatform::send(const PlatformCommand& command) {
  const bool faulted = core_.status().state == OperatingState::Fault;
  CommandResult result = core_.apply(command);
  if (faulted && core_.status().state != OperatingState::Fault) actuation_->clearFault();
  return result;
}

ArmPair TwinPlatform::measuredPositions() const {
  return {readings_[0].position, readings_[1].position};
}

void TwinPlatform::advance(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0.0) {
    throw std::invalid_argument("advance: seconds must be finite and >= 0, not " +
                                std::to_string(seconds));
  }
  requested_ += seconds;
  const auto target = static_cast<std::uint64_t>(std::llround(requested_ / core_.limits().cycle));
  while (core_.cycles() < target) {
    if (clock_ == ClockKind::Wall) pacer_.waitUntil(core_.time());
    runCycle();
  }
  if (clock_ == ClockKind::Wall) pacer_.waitUntil(requested_);
}

void TwinPlatform::place(Arm arm, const ArmStart& start) {
  actuation_->place(arm, start);
  readings_ = readAll(*actuation_);
}

void TwinPlatform::runCycle() {
  previous_position_ = measuredPositions();
  core_.cycle(previous_position_);
  for (Arm arm : raven::kArms) {
    actuation_->drive(arm, core_.setpoint(arm));
  }
  world_.step();
  if (after_step_) after_step_(world_);
  readings_ = readAll(*actuation_);
  if (const std::string why = actuation_->fault();
      !why.empty() && core_.status().state != OperatingState::Fault) {
    core_.fault(why);
  }
}

JointSample TwinPlatform::measuredJs(Arm arm) const {
  const ActuatorReadings& r = readings_[slot(arm)];
  return {now(), r.position, r.velocity, r.effort};
}

JointSample TwinPlatform::setpointJs(Arm arm) const {
  return {now(), core_.setpoint(arm), core_.setpointVelocity(arm), ArmJoints::Zero()};
}

PoseSample TwinPlatform::measuredCp(Arm arm) const {
  return {now(), core_.reportedPose(arm, readings_[slot(arm)].position)};
}

PoseSample TwinPlatform::setpointCp(Arm arm) const {
  return {now(), core_.reportedPose(arm, core_.setpoint(arm))};
}

std::optional<GrasperForces> TwinPlatform::measuredCf(Arm arm) const {
  const auto& jaws = arms_.jawBodies(arm);
  return graspForces(world_, jaws, arms_.bodies(arm), world_.body(jaws[0]).pose().translation());
}

std::optional<RavenStateSnapshot> TwinPlatform::ravenState() const {
  return makeRavenState({core_, readings_, previous_position_});
}

/// Everything TwinPlatform::saveState captures.
struct TwinPlatform::State {
  std::shared_ptr<const ambf_like::WorldState> world;
  std::any actuation;
  raven::PerArm<ActuatorReadings> readings;
  ArmPair previous_position;
  RavenCore core;
  double requested;
};

std::shared_ptr<const TwinPlatform::State> TwinPlatform::saveState() {
  if (clock_ == ClockKind::Wall) {
    throw std::logic_error("a twin on the wall clock has no state to save: use the simulated one");
  }
  return std::make_shared<const State>(State{world_.saveState(), actuation_->state(), readings_,
                                             previous_position_, core_, requested_});
}

void TwinPlatform::restoreState(const State& state) {
  world_.restoreState(*state.world);
  actuation_->restore(state.actuation);
  readings_ = state.readings;
  previous_position_ = state.previous_position;
  core_ = state.core;
  requested_ = state.requested;
}

}  // namespace twin
