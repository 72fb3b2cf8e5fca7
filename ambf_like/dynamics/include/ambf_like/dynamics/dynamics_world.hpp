#pragma once
// Bullet's soft-body worlds, doing continuous collision work only when a body asks for it.

#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <BulletSoftBody/btSoftMultiBodyDynamicsWorld.h>

#include <functional>
#include <utility>

namespace ambf_like::detail {

/// A Bullet soft-body world (btSoftRigidDynamicsWorld, or btSoftMultiBodyDynamicsWorld when
/// articulations are stepped too) that sweeps AABBs and creates predictive contacts only while
/// some body has a CCD motion threshold. Bullet otherwise predicts every moving body's next
/// pose and widens its AABB to cover it each step; no body this library builds sets a threshold
/// (at 1 ms a body at 1 m/s moves 1 mm, inside the contact margins), and that work was 6 % of a
/// Raven-II step.
template <class SoftWorld>
class DynamicsWorld : public SoftWorld {
 public:
  using SoftWorld::SoftWorld;

 protected:
  // Bullet calls this after predicting motion and before collision detection, so the switch
  // below also decides whether this step's AABBs are swept.
  void createPredictiveContacts(btScalar time_step) override {
    bool any_ccd = false;
    const auto& moving = this->m_nonStaticRigidBodies;
    for (int i = 0; i < moving.size() && !any_ccd; ++i) {
      any_ccd = moving[i]->getCcdSquareMotionThreshold() > 0.0;
    }
    this->getDispatchInfo().m_useContinuous = any_ccd;
    if (any_ccd) SoftWorld::createPredictiveContacts(time_step);
  }
};

/// The world with articulations: it also reports the moment each step's free motion (joint
/// torques, gravity, Coriolis) has been applied to the articulations' velocities, before
/// contacts and limits act, so their servos can tell the two apart.
class ArticulatedDynamicsWorld final : public DynamicsWorld<btSoftMultiBodyDynamicsWorld> {
 public:
  using DynamicsWorld::DynamicsWorld;
  void setFreeMotionListener(std::function<void()> listener) { listener_ = std::move(listener); }

 protected:
  void solveExternalForces(btContactSolverInfo& info) override {
    DynamicsWorld::solveExternalForces(info);
    if (listener_) listener_();
  }

 private:
  std::function<void()> listener_;
};

}  // namespace ambf_like::detail
