#pragma once
// A stop on a sum of joint coordinates: where two parts that separate joints move meet, as a
// gripper's jaws do when they close on each other.

#include <memory>
#include <string>
#include <vector>

class btMultiBodyDynamicsWorld;

namespace ambf_like {

namespace detail {
class CoupledLimitConstraint;
}

/// sum_i gains[i] * q_i >= lower, over joints of one articulation (reduced coordinates), q_i each
/// joint's coordinate in its model's convention (rad or m).
struct CoupledStopSpec {
  std::vector<std::string> joints;  ///< the World's joint names (qualified or unique plain)
  std::vector<double> gains;        ///< one per joint, finite
  double lower = 0.0;
};

/// A CoupledStop in a World (World::addCoupledStop): it pushes the joints apart along the gains
/// when their sum reaches `lower`, and never pulls.
class CoupledStop {
 public:
  /// Its `constraint` goes into `world` while near its bound (watch), until destroyed.
  CoupledStop(CoupledStopSpec spec, std::unique_ptr<detail::CoupledLimitConstraint> constraint,
              btMultiBodyDynamicsWorld& world, double step);
  ~CoupledStop();
  CoupledStop(const CoupledStop&) = delete;
  CoupledStop& operator=(const CoupledStop&) = delete;

  const CoupledStopSpec& spec() const { return spec_; }
  /// Moves the bound to `lower` (finite; a calibration that places the stop after the model's
  /// load): the sum stops there from the next step.
  void setLower(double lower);
  /// Makes the stop give (finite, >= 0): past its bound the sum goes `compliance` (rad per N m,
  /// or m per N) per unit of the force it is pressed with, as a spring; 0 is rigid.
  void setCompliance(double compliance);
  /// The generalised force (N m or N, >= 0) the stop applied along the gains in the last step:
  /// joint i felt gains[i] times it.
  double force() const;
  /// sum_i gains[i] q_i - lower now (< 0: pressed past the stop by that much).
  double gap() const;
  /// Before a step of `dt`: in the world's solve within two steps' travel and a millimetre (or
  /// milliradian) of the bound, out of it beyond (an engaged constraint costs the solver's
  /// set-up every step). Which constraints are in the world is part of World::saveState.
  void watch(double dt);

 private:
  bool engaged() const;  ///< in the world's solve now

  CoupledStopSpec spec_;
  std::unique_ptr<detail::CoupledLimitConstraint> constraint_;
  btMultiBodyDynamicsWorld& world_;
  double step_;
};

}  // namespace ambf_like
