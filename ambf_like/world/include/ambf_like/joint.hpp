#pragma once
// A joint of the running simulation: its coordinate, and position/velocity/effort commands.

#include <memory>
#include <string>

#include "ambf_like/joint_spec.hpp"
#include "ambf_like/pid_controller.hpp"

namespace ambf_like {

namespace detail {
class JointDynamics;
class JointDynamicsMemory;
struct JointActuation;
}  // namespace detail

/// What currently drives a joint.
enum class JointDrive { Free, Position, Velocity, Effort };

/// One joint of a World. Commands persist until replaced; the controller runs every step.
class Joint {
 public:
  /// Built by World over the physics of its formulation (maximal or reduced coordinates).
  Joint(JointSpec spec, std::unique_ptr<detail::JointDynamics> dynamics);
  ~Joint();
  Joint(const Joint&) = delete;
  Joint& operator=(const Joint&) = delete;

  const std::string& name() const { return spec_.name; }
  const JointSpec& spec() const { return spec_; }
  /// Revolute, continuous and prismatic joints that are not passive accept commands.
  bool isControllable() const;

  /// Joint coordinate (rad, or m for prismatic), continuous across turns.
  double position() const { return position_; }
  /// Rate of the coordinate (rad/s or m/s), from the bodies' velocities.
  double velocity() const;
  /// Generalised force (N m or N) the joint's actuator and limits applied in the last step.
  double effort() const;

  JointDrive drive() const { return drive_; }
  double target() const { return target_; }

  /// Tracks `position` with the joint's PID; returns the target after clamping to the limits.
  /// Throws std::invalid_argument for NaN/inf or a joint that takes no commands.
  double commandPosition(double position);
  void commandVelocity(double velocity);
  void commandEffort(double effort);
  /// Stops driving the joint (motor off, no effort).
  void release();
  /// Whether the joint is a coordinate of an articulation (reduced coordinates): transmissions
  /// and place() need it.
  bool inArticulation() const;
  /// Puts the joint at `position` moving at `velocity` (a replay's start), in reduced
  /// coordinates. Throws std::invalid_argument for NaN/inf, a joint without a coordinate or one
  /// in maximal coordinates (two free bodies, placed by their poses).
  void place(double position, double velocity);

  /// World internals: apply the controller before a step, read the coordinate after it.
  void applyControl(double dt);
  void updateCoordinate();
  detail::JointDynamics& dynamics() { return *dynamics_; }

  /// What the joint's next steps depend on beyond its bodies (World::saveState).
  struct State {
    PidController pid;
    JointDrive drive = JointDrive::Free;
    double target = 0.0, position = 0.0, last_raw = 0.0;
    std::shared_ptr<const detail::JointDynamicsMemory> dynamics;  ///< its formulation's
  };
  State state() const;
  void restore(const State& state);

 private:
  void requireCommandable(const char* what, double value) const;
  void setDrive(JointDrive drive, double target);
  void setMotor(detail::JointActuation& actuation, double velocity) const;
  detail::JointActuation drivenActuation(double dt);
  /// The joint damping's effort over a step of dt, integrated exactly on the axis inertia.
  double dampingEffort(double dt) const;

  JointSpec spec_;
  std::unique_ptr<detail::JointDynamics> dynamics_;
  PidController pid_;
  JointDrive drive_ = JointDrive::Free;
  double target_ = 0.0;
  double position_ = 0.0;
  double last_raw_ = 0.0;
};

}  // namespace ambf_like
