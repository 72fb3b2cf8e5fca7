#pragma once
// The Bullet objects a World steps: collision pipeline, solver and dynamics world.

#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "ambf_like/elastic_solve_stats.hpp"
#include "ambf_like/soft_body_spec.hpp"

class btCollisionDispatcher;
class btCollisionWorld;
class btDiscreteDynamicsWorld;
class btMultiBodyDynamicsWorld;
class btSoftBody;
struct btSoftBodyWorldInfo;

namespace ambf_like::detail {

struct NodeContactImpulse;
class SoftBodyStepSolver;

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
  /// many substeps (SoftBodyStepSolver), its tetrahedra the `material`'s elasticity if given.
  void addSoftBody(btSoftBody& body, std::optional<int> coulomb_substeps,
                   const std::optional<SoftMaterial>& material);
  void removeSoftBody(btSoftBody& body);
  /// The impulses of the last step's Coulomb contacts.
  const std::vector<NodeContactImpulse>& coulombImpulses() const;
  /// The soft bodies' solver (its state goes into World::saveState).
  SoftBodyStepSolver& softBodySolver();
  /// What the implicit steps of `body` (with a material) took so far.
  ElasticSolveStats elasticStats(const btSoftBody& body) const;
  /// The world articulations go into; only when built with articulations.
  btMultiBodyDynamicsWorld& articulations();
  /// Called in every step once the articulations' free motion is in their velocities.
  void setFreeMotionListener(std::function<void()> listener);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Call after adding a collision object to `world`: every 1,024 proxies the broadphase's trees
/// are rebuilt balanced. Bullet inserts a proxy by descending towards its nearest neighbour, so
/// bodies added in a row (a chain) make a tree as deep as it is long, and n insertions cost n^2
/// (a 20,000-body chain: most of a minute).
void keepBroadphaseBalanced(btCollisionWorld& world);

}  // namespace ambf_like::detail
