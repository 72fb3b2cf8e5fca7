#include "ambf_like/dynamics/rotor_response.hpp"

#include <Eigen/Dense>
#include <stdexcept>

#include "ambf_like/dynamics/joint_space_servo.hpp"

namespace ambf_like::detail {

void carryRotors(btMultiBody& body, const JointSpaceServo& servo) {
  if (!body.hasFixedBase()) {
    throw std::logic_error("rotors: an articulation with motors needs a fixed base");
  }
  // Bullet leaves a multibody's user pointer to its owner; this library's is its rotors.
  body.setUserPointer(const_cast<JointSpaceServo*>(&servo));
}

const JointSpaceServo* rotorsOf(const btMultiBody& body) {
  return static_cast<const JointSpaceServo*>(body.getUserPointer());
}

void impulseResponse(const btMultiBody& body, const btScalar* jacobian, btScalar* response,
                     btAlignedObjectArray<btScalar>& scratch_r,
                     btAlignedObjectArray<btVector3>& scratch_v) {
  const JointSpaceServo* rotors = rotorsOf(body);
  // A world state saved before the transmission was added restores a servo without one.
  if (rotors == nullptr || !rotors->hasTransmission()) {
    body.calcAccelerationDeltasMultiDof(jacobian, response, scratch_r, scratch_v);
    return;
  }
  const int dofs = body.getNumDofs();
  for (int i = 0; i < 6; ++i) response[i] = 0.0;  // a fixed base
  Eigen::Map<Eigen::VectorXd>(response + 6, dofs).noalias() =
      rotors->reflectedInverse() * Eigen::Map<const Eigen::VectorXd>(jacobian + 6, dofs);
}

}  // namespace ambf_like::detail
