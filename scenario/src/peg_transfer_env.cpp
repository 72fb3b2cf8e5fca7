#include "scenario/peg_transfer_env.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "scenario/peg_transfer.hpp"
#include "scenario/robot_observation.hpp"

namespace scenario {

namespace {

/// Both arms' kinematics of `profile`, left first.
raven::PerArm<raven::ArmKinematics> armsOf(const raven::PlatformProfile& profile) {
  return {raven::ArmKinematics::of(profile, raven::Arm::Left),
          raven::ArmKinematics::of(profile, raven::Arm::Right)};
}

}  // namespace

PegTransferEnv::PegTransferEnv(PegTransferEnvOptions options)
    : options_(std::move(options)),
      profile_(raven::builtinProfile("physical")),
      kinematics_(armsOf(profile_)) {
  if (options_.control == EnvControl::Period &&
      !(options_.period >= 0.002 && options_.period <= 10.0)) {
    throw std::invalid_argument("a step's period must lie in [0.002, 10] s, not " +
                                std::to_string(options_.period));
  }
}

PegTransferEnv::~PegTransferEnv() = default;

ScriptedSession& PegTransferEnv::session() {
  if (!session_) throw std::logic_error("the environment needs reset() before step()");
  return *session_;
}

twin::TwinPlatform& PegTransferEnv::twin() {
  return session().twin();
}

Eigen::VectorXd PegTransferEnv::reset(std::uint64_t seed) {
  PegTransferOptions run;
  run.seed = seed;
  run.launch_file = options_.launch_file;
  run.actuation = options_.actuation;
  SceneVariation variation =
      options_.randomize ? SceneVariation::draw(seed, options_.ranges) : SceneVariation{};
  variation.seed = seed;
  variation_ = variation;
  expert_.reset();
  ++episode_;
  scene_.reset();
  session_.reset();  // the old twin goes before the new one is built
  controller::ControllerOptions control;
  control.following_limit = followingLimit();
  control.arrival = arrival();
  session_ = std::make_unique<ScriptedSession>(pegTransferTwin(run, variation), control);
  session_->makeReady(options_.time_limit);
  expert_.emplace(pegTransferOperators(layout_, options_.squeeze));
  const ambf_like::World& world = session_->twin().world();
  scene_ = std::make_unique<twin::WorldPerception>(world);
  for (std::size_t i = 0; i < rings_.size(); ++i) {
    rings_[i] = &world.softBody(layout_.jobs[i].ring);
  }
  placed_ = countPlaced();
  failure_.clear();
  last_observation_ = observe();
  return last_observation_;
}

PegTransferStep PegTransferEnv::step(const Eigen::VectorXd& action) {
  controller::DualPlatformController& controller = session().controller();
  const controller::ArmPair next =
      targetsOf(options_.action, action, controller.commanded(), kinematics_, profile_.home);
  if (options_.control == EnvControl::Waypoint) {
    return guardedStep([&] { return controller.moveTo(next).refused; });
  }
  const int steps =
      std::max(1, static_cast<int>(std::lround(options_.period / controller.period())));
  return guardedStep([&] { return controller.moveFor(next, steps).refused; });
}

PegTransferStep PegTransferEnv::step(const recording::GamepadState& pad) {
  return guardedStep([&] { return session().controller().manual(pad).refused; });
}

PegTransferStep PegTransferEnv::guardedStep(const std::function<std::size_t()>& run) {
  session();  // reset() first
  if (!failure_.empty()) {
    throw std::logic_error("the episode ended when its world failed (" + failure_ +
                           "): reset() before step()");
  }
  try {
    return finishStep(run());
  } catch (const ambf_like::SimulationDiverged& e) {
    failure_ = e.what();
    PegTransferStep out;
    out.observation = last_observation_;
    out.placed = placed_;
    out.truncated = true;
    out.failure = failure_;
    return out;
  }
}

Eigen::VectorXd PegTransferEnv::expertAction(bool from_state) {
  if (!failure_.empty()) throw std::logic_error("the episode ended when its world failed");
  controller::DualPlatformController& controller = session().controller();
  const controller::ArmPair& current = controller.commanded();
  if (from_state) {
    for (raven::Arm arm : raven::kArms) {
      (*expert_)[raven::slot(arm)].resume(current[raven::slot(arm)], *scene_);
    }
  }
  const twin::TwinPlatform& twin = session().twin();
  const controller::ArmPair targets{
      (*expert_)[0].next(current[0], twin.measuredJs(raven::Arm::Left).position, *scene_),
      (*expert_)[1].next(current[1], twin.measuredJs(raven::Arm::Right).position, *scene_)};
  return actionFor(options_.action, targets, current, kinematics_);
}

std::array<int, 2> PegTransferEnv::expertJobsFinished() const {
  if (!expert_) return {0, 0};
  return {static_cast<int>((*expert_)[0].finished()), static_cast<int>((*expert_)[1].finished())};
}

Eigen::VectorXd PegTransferEnv::actionLow() const {
  return actionBounds(options_.action, profile_.limits).low;
}

Eigen::VectorXd PegTransferEnv::actionHigh() const {
  return actionBounds(options_.action, profile_.limits).high;
}

Eigen::Matrix<double, 2, 3, Eigen::RowMajor> PegTransferEnv::toolPoints(
    const Eigen::Matrix<double, 14, 1>& joints) {
  static const raven::PerArm<raven::ArmKinematics> arms = armsOf(raven::builtinProfile("physical"));
  Eigen::Matrix<double, 2, 3, Eigen::RowMajor> out;
  for (raven::Arm arm : raven::kArms) {
    const int a = raven::index(arm);
    const raven::ArmJoints q = joints.segment<raven::kJointCount>(raven::kJointCount * a);
    out.row(a) = arms[raven::slot(arm)].toolPose(q).translation().transpose();
  }
  return out;
}

double PegTransferEnv::time() const {
  return session_ ? session_->twin().now() : 0.0;
}

PegTransferStep PegTransferEnv::finishStep(std::size_t refused) {
  PegTransferStep out;
  const int before = placed_;
  placed_ = countPlaced();
  out.observation = observe();
  last_observation_ = out.observation;
  out.reward = placed_ - before;
  out.placed = placed_;
  out.terminated = placed_ == static_cast<int>(rings_.size());
  out.faulted = session_->twin().operatingStatus().state == bridge::OperatingState::Fault;
  out.truncated = !out.terminated && (out.faulted || time() >= options_.time_limit);
  out.refused = refused;
  return out;
}

int PegTransferEnv::countPlaced() const {
  return ringsPlaced(*scene_, layout_);
}

Eigen::VectorXd PegTransferEnv::observe() const {
  Eigen::VectorXd o(observation::kSize);
  observeRobot(session_->twin(), session_->controller().commanded(), o);
  for (std::size_t i = 0; i < rings_.size(); ++i) {
    o.segment<observation::kRings.item_size>(observation::item(observation::kRings, i).start) =
        rings_[i]->centerOfMass();
  }
  return o;
}

/// Everything PegTransferEnv::saveState captures.
struct PegTransferEnv::State {
  std::uint64_t episode;
  std::shared_ptr<const twin::TwinPlatform::State> twin;
  controller::DualPlatformController::State controller;
  raven::PerArm<ArmRoutine> expert;
  int placed;
  Eigen::VectorXd last_observation;
};

std::shared_ptr<const PegTransferEnv::State> PegTransferEnv::saveState() {
  ScriptedSession& s = session();
  if (!failure_.empty()) throw std::logic_error("the episode ended when its world failed");
  return std::make_shared<const State>(State{episode_, s.twin().saveState(), s.controller().state(),
                                             *expert_, placed_, last_observation_});
}

void PegTransferEnv::restoreState(const State& state) {
  if (state.episode != episode_) {
    throw std::invalid_argument("a state of another episode (reset() builds a new world)");
  }
  session_->twin().restoreState(*state.twin);
  session_->controller().restore(state.controller);
  expert_ = state.expert;
  placed_ = state.placed;
  last_observation_ = state.last_observation;
}

}  // namespace scenario
