#include "ambf_like/joint.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "ambf_like/dynamics/joint_dynamics.hpp"
#include "common/wrap_angle.hpp"

namespace ambf_like {

namespace {

const char* typeName(JointType type) {
  switch (type) {
    case JointType::Revolute:
      return "revolute";
    case JointType::Continuous:
      return "continuous";
    case JointType::Prismatic:
      return "prismatic";
    case JointType::Fixed:
      return "fixed";
    case JointType::P2P:
      return "p2p";
    case JointType::LinearSpring:
      return "linear spring";
    case JointType::TorsionSpring:
      return "torsion spring";
    case JointType::ConeTwist:
      return "cone twist";
    case JointType::SixDof:
      return "six dof";
    case JointType::SixDofSpring:
      return "six dof spring";
  }
  return "?";
}

}  // namespace

Joint::Joint(JointSpec spec, std::unique_ptr<detail::JointDynamics> dynamics)
    : spec_(std::move(spec)), dynamics_(std::move(dynamics)), pid_(spec_.controller) {
  last_raw_ = dynamics_->coordinate();
  position_ = last_raw_;
}

Joint::~Joint() = default;

bool Joint::isControllable() const {
  const bool commandable_type = spec_.type == JointType::Revolute ||
                                spec_.type == JointType::Continuous ||
                                spec_.type == JointType::Prismatic;
  return commandable_type && !spec_.passive && spec_.enable_motor;
}

bool Joint::inArticulation() const {
  return dynamics_->servoDof().servo != nullptr;
}

void Joint::place(double position, double velocity) {
  if (!std::isfinite(position) || !std::isfinite(velocity)) {
    throw std::invalid_argument("joint '" + spec_.name + "': cannot be placed at " +
                                std::to_string(position) + " moving at " +
                                std::to_string(velocity));
  }
  if (!spec_.isSingleAxis() || !dynamics_->place(position, velocity)) {
    throw std::invalid_argument("joint '" + spec_.name + "' (" + typeName(spec_.type) +
                                ") cannot be placed: only a joint of an articulation (reduced "
                                "coordinates) can");
  }
  position_ = position;
  last_raw_ = dynamics_->coordinate();
}

void Joint::updateCoordinate() {
  const double raw = dynamics_->coordinate();
  if (spec_.isAngular()) {
    position_ += common::wrapToPi(raw - last_raw_);
  } else {
    position_ = raw;
  }
  last_raw_ = raw;
}

double Joint::velocity() const {
  return spec_.isSingleAxis() ? dynamics_->velocity() : 0.0;
}

double Joint::effort() const {
  return spec_.isSingleAxis() ? dynamics_->effort() : 0.0;
}

void Joint::requireCommandable(const char* what, double value) const {
  if (!isControllable()) {
    throw std::invalid_argument(
        "joint '" + spec_.name + "' (" + typeName(spec_.type) + (spec_.passive ? ", passive" : "") +
        (spec_.enable_motor ? "" : ", motor disabled") + ") takes no commands");
  }
  if (!std::isfinite(value)) {
    throw std::invalid_argument("joint '" + spec_.name + "': " + what + " command " +
                                std::to_string(value) + " is not a finite number; ignored");
  }
}

void Joint::setDrive(JointDrive drive, double target) {
  if (drive != drive_) pid_.reset();
  drive_ = drive;
  target_ = target;
}

double Joint::commandPosition(double position) {
  requireCommandable("position", position);
  if (spec_.limits) position = std::clamp(position, spec_.limits->low, spec_.limits->high);
  setDrive(JointDrive::Position, position);
  return position;
}

void Joint::commandVelocity(double velocity) {
  requireCommandable("velocity", velocity);
  setDrive(JointDrive::Velocity, velocity);
}

void Joint::commandEffort(double effort) {
  requireCommandable("effort", effort);
  setDrive(JointDrive::Effort, effort);
}

void Joint::release() {
  setDrive(JointDrive::Free, 0.0);
}

void Joint::setMotor(detail::JointActuation& actuation, double velocity) const {
  if (spec_.max_velocity)
    velocity = std::clamp(velocity, -*spec_.max_velocity, *spec_.max_velocity);
  actuation.motor_on = true;
  actuation.motor_velocity = velocity;
  actuation.motor_max_impulse = spec_.max_motor_impulse;
}

detail::JointActuation Joint::drivenActuation(double dt) {
  detail::JointActuation actuation;
  switch (drive_) {
    case JointDrive::Free:
      break;
    case JointDrive::Position: {
      const double error = target_ - position_;
      const double output = pid_.update(error, dt);
      switch (spec_.output) {
        case ControlOutput::Effort:
          actuation.effort = output;
          break;
        case ControlOutput::Velocity:
          setMotor(actuation, output);
          break;
        case ControlOutput::Position:
          // Close half the error each step (the deadbeat e/dt is only marginally stable in
          // Bullet's iterative solver: a slider then oscillates step to step), no faster than
          // `max velocity` (setMotor caps it): without a cap a large jump asks for hundreds of
          // rad/s and the torque-limited joint overshoots wildly.
          setMotor(actuation, error / (2.0 * dt));
          break;
      }
      break;
    }
    case JointDrive::Velocity:
      setMotor(actuation, target_);
      break;
    case JointDrive::Effort:
      actuation.effort = target_;
      break;
  }
  return actuation;
}

void Joint::applyControl(double dt) {
  const bool springs_damp_themselves =
      spec_.type == JointType::LinearSpring || spec_.type == JointType::TorsionSpring;
  if (!spec_.isSingleAxis() || springs_damp_themselves) return;
  auto actuation = isControllable() ? drivenActuation(dt) : detail::JointActuation{};
  if (spec_.damping > 0.0) actuation.effort -= dampingEffort(dt);
  dynamics_->actuate(actuation, dt);
}

double Joint::dampingEffort(double dt) const {
  // A damper c on an inertia I over a step h takes v to v exp(-c h / I): the effort that does
  // that, I (1 - exp(-c h / I)) / h, is c for a light damper and at most what stops the joint
  // within the step. The explicit c v overshoots (and grows) once c h / I passes 2: a joint
  // damped by 5 N m s on a 1e-9 kg m^2 link flung it at 22 km/s at its second step.
  const double inertia = dynamics_->axisInertia();
  const double damping = spec_.damping;
  if (!(inertia < std::numeric_limits<double>::infinity())) return damping * velocity();
  return inertia / dt * -std::expm1(-damping * dt / inertia) * velocity();
}

Joint::State Joint::state() const {
  return {pid_, drive_, target_, position_, last_raw_, dynamics_->memory()};
}

void Joint::restore(const State& state) {
  if (state.dynamics) dynamics_->recall(state.dynamics.get());
  pid_ = state.pid;
  drive_ = state.drive;
  target_ = state.target;
  position_ = state.position;
  last_raw_ = state.last_raw;
}

}  // namespace ambf_like
