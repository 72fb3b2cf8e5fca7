#pragma once
// The Bullet objects a World steps: collision pipeline, solver and dynamics world.

#include <functional>
#include <memory>
#include <optional>
#include <vector>

class btCollisionDispatcher;
class btDiscreteDynamicsWorld;
class btMultiBodyDynamicsWorld;
class btSoftBody;
struct btSoftBodyWorldInfo;

namespace ambf_like::detail {

struct NodeContactImpulse;

/// Bullet's soft-rigid world with its solver, or, when articulations are to be stepped too,
/// its soft-multibody world. The soft-rigid one is kept whenever it suffices: the two differ in
/// their island and solver set-up, and the peg-transfer scene's outcomes are measured on it.
class BulletWorld {
 public:
  explicit BulletWorld(bool with_articulations);
  ~BulletWorld();
  BulletWorld(const BulletWorld&) = delete;
  BulletWorld& operator=(const BulletWorld&) = delete;

  btDiscreteDynamicsWorld& dynamics();
  btCollisionDispatcher& dispatcher();
  const btCollisionDispatcher& dispatcher() const;
  btSoftBodyWorldInfo& softBodyInfo();
  /// With `coulomb_substeps` set, its rigid contacts get Coulomb friction and its step that
  /// many substeps (CoulombContactSolver).
  void addSoftBody(btSoftBody& body, std::optional<int> coulomb_substeps);
  void removeSoftBody(btSoftBody& body);
  /// The impulses of the last step's Coulomb contacts.
  const std::vector<NodeContactImpulse>& coulombImpulses() const;
  /// The world articulations go into; only when built with articulations.
  btMultiBodyDynamicsWorld& articulations();
  /// Called in every step once the articulations' free motion is in their velocities.
  void setFreeMotionListener(std::function<void()> listener);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ambf_like::detail
