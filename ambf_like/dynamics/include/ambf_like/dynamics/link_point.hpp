#pragma once
// A point of an articulation's link as a soft body meets it: how fast it moves, and an impulse
// given to the articulation there.

#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

namespace ambf_like::detail {

/// The moving articulation link behind `object` (a link's collider, not its fixed base), or
/// null.
btMultiBodyLinkCollider* movingLink(const btCollisionObject* object);

/// Velocity of the link's material point at `point` (world).
btVector3 linkPointVelocity(const btMultiBodyLinkCollider& link, const btVector3& point);

/// Gives the articulation `impulse` (world, N s) at `point` of the link: its joint velocities
/// change by impulseResponse's answer to J^T p (its links' and any rotors' inertia).
void applyLinkImpulse(btMultiBodyLinkCollider& link, const btVector3& point,
                      const btVector3& impulse);

}  // namespace ambf_like::detail
