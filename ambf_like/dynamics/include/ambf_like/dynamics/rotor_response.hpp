#pragma once
// How an articulation's joints answer an impulse when motors' rotors turn with them.

#include <BulletDynamics/Featherstone/btMultiBody.h>

namespace ambf_like::detail {

class JointSpaceServo;

/// Marks `body` (fixed base) as moving together with the rotors of `servo`'s transmission:
/// contacts, limits and soft bodies then stop links and rotors as one (as MuJoCo's armature).
void carryRotors(btMultiBody& body, const JointSpaceServo& servo);

/// The servo whose rotors move with `body`, or null.
const JointSpaceServo* rotorsOf(const btMultiBody& body);

/// The change of `body`'s velocities (6 + dofs, the base's first) a unit impulse along
/// `jacobian` causes: (M + A + h D)^-1 J^T on the joints, with the rotors' reflected inertia A
/// and implicit viscous friction D (JointSpaceServo::reflectedInverse), when it carries rotors;
/// Bullet's articulated-body answer M^-1 J^T otherwise.
void impulseResponse(const btMultiBody& body, const btScalar* jacobian, btScalar* response,
                     btAlignedObjectArray<btScalar>& scratch_r,
                     btAlignedObjectArray<btVector3>& scratch_v);

}  // namespace ambf_like::detail
