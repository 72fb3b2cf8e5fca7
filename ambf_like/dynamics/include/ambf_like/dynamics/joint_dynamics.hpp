#pragma once
// How a Joint reads and actuates its coordinate in one Bullet formulation.

#include <memory>

class btMultiBody;

namespace ambf_like::detail {

class JointSpaceServo;

/// What a joint's drive asks of the physics for the next step.
struct JointActuation {
  bool motor_on = false;
  double motor_velocity = 0.0;     ///< rad/s or m/s, already within the joint's speed limit
  double motor_max_impulse = 0.0;  ///< N m s or N s per step
  double effort = 0.0;             ///< N m or N, on top of the motor
};

/// What a formulation's next steps and readings depend on beyond its bodies (World::saveState).
class JointDynamicsMemory {
 public:
  virtual ~JointDynamicsMemory() = default;
};

/// A joint's coordinate as the physics sees it: maximal coordinates (a constraint between two
/// rigid bodies) or reduced ones (a degree of freedom of an articulation).
class JointDynamics {
 public:
  virtual ~JointDynamics() = default;
  /// Joint coordinate (rad or m); angular ones may wrap at +-pi.
  virtual double coordinate() const = 0;
  virtual double velocity() const = 0;
  /// Inertia (kg m^2, or kg for a sliding joint) that the joint's own generalised force moves:
  /// what a damper on it acts against. Infinite where nothing it joins can move.
  virtual double axisInertia() const = 0;
  /// Generalised force the motor, the limits and the effort applied in the last step.
  virtual double effort() const = 0;
  /// Sets the motor and applies the effort for the coming step.
  virtual void actuate(const JointActuation& actuation, double dt) = 0;
  /// Where its torques are solved in joint space: its articulation's servo and its degree of
  /// freedom there; none in maximal coordinates.
  struct ServoDof {
    JointSpaceServo* servo = nullptr;
    int dof = -1;
    btMultiBody* multibody = nullptr;  ///< the articulation's
  };
  virtual ServoDof servoDof() const { return {}; }
  /// Puts the coordinate at `coordinate` moving at `velocity`; false where the formulation
  /// cannot (a constraint between two free bodies).
  virtual bool place(double /*coordinate*/, double /*velocity*/) { return false; }
  /// Its memory (null: it keeps none), and taking a saved one back.
  virtual std::shared_ptr<const JointDynamicsMemory> memory() const { return nullptr; }
  virtual void recall(const JointDynamicsMemory* /*memory*/) {}
};

}  // namespace ambf_like::detail
