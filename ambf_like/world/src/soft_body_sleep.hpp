#pragma once
// Deactivation for soft bodies: Bullet puts resting rigid bodies to sleep but steps every soft
// body at every step, resting or not.

#include <LinearMath/btVector3.h>

#include <memory>
#include <vector>

#include "ambf_like/rigid_body.hpp"
#include "ambf_like/scene_spec.hpp"
#include "ambf_like/soft_body.hpp"

class btCollisionObject;
class btCollisionWorld;

namespace ambf_like::detail {

/// An axis-aligned box in world coordinates.
struct Box {
  btVector3 min, max;
  /// True when the boxes are closer than `gap` along every axis.
  bool overlaps(const Box& other, double gap) const;
};

/// Puts soft bodies that have rested long enough to sleep (Bullet's default soft-body solver
/// then skips them) and wakes them when a moving body comes near or an anchor holds them.
class SoftBodySleeper {
 public:
  /// For a world of `soft_bodies` soft bodies; `world` answers the precise proximity queries
  /// (shapes, not just their bounding boxes).
  SoftBodySleeper(const SoftBodySleep& settings, btCollisionWorld& world, std::size_t soft_bodies)
      : settings_(settings), world_(world), rest_(soft_bodies) {}

  /// Before a step: wakes sleepers that something moving approaches or an anchor holds. A
  /// sleeper keeps reporting the contacts it fell asleep on; what it collected since is dropped
  /// (Bullet clears contacts only for bodies it steps).
  void beforeStep(const std::vector<std::unique_ptr<SoftBody>>& soft,
                  const std::vector<std::unique_ptr<RigidBody>>& rigid);
  /// After a step of `h` seconds: follows the awake bodies' windows and puts rested ones to sleep.
  void afterStep(const std::vector<std::unique_ptr<SoftBody>>& soft, double h);

  /// A body's resting window: node positions when it began, and how long it has lasted.
  struct Rest {
    std::vector<btVector3> start;
    double rested = 0.0;                        ///< s
    int rigid_contacts = 0, soft_contacts = 0;  ///< when it fell asleep
    bool resting(const SoftBodySleep& settings) const { return rested >= settings.time; }
  };
  /// Every body's window (World::saveState).
  const std::vector<Rest>& state() const { return rest_; }
  void restore(const std::vector<Rest>& state) { rest_ = state; }

 private:
  bool comesWithinWakeDistance(btCollisionObject& mover, const Box& bounds) const;
  bool approached(const SoftBody& sleeper, const std::vector<std::unique_ptr<SoftBody>>& soft,
                  const std::vector<std::unique_ptr<RigidBody>>& rigid) const;

  SoftBodySleep settings_;
  btCollisionWorld& world_;
  std::vector<Rest> rest_;
};

}  // namespace ambf_like::detail
