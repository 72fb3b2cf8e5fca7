#include "ambf_like/dynamics/bullet_world.hpp"

#include <BulletDynamics/ConstraintSolver/btSequentialImpulseConstraintSolver.h>
#include <BulletSoftBody/btSoftBodyRigidBodyCollisionConfiguration.h>
#include <BulletSoftBody/btSoftMultiBodyDynamicsWorld.h>
#include <BulletSoftBody/btSoftRigidDynamicsWorld.h>
#include <btBulletCollisionCommon.h>

#include <stdexcept>

#include "ambf_like/dynamics/dynamics_world.hpp"
#include "ambf_like/dynamics/rotor_contact_solver.hpp"
#include "ambf_like/dynamics/sequential_impulse_solver.hpp"
#include "ambf_like/dynamics/soft_body_step_solver.hpp"

namespace ambf_like::detail {

struct BulletWorld::Impl {
  btSoftBodyRigidBodyCollisionConfiguration collision_config;
  btCollisionDispatcher dispatcher{&collision_config};
  btDbvtBroadphase broadphase;
  std::unique_ptr<btConstraintSolver> solver;
  SoftBodyStepSolver soft_solver;  ///< outlives the world that uses it
  std::unique_ptr<btDiscreteDynamicsWorld> world;
  btSoftRigidDynamicsWorld* soft_rigid = nullptr;      ///< world, when without articulations
  ArticulatedDynamicsWorld* soft_multibody = nullptr;  ///< world, when with them
};

BulletWorld::BulletWorld(bool with_articulations) : impl_(std::make_unique<Impl>()) {
  auto& i = *impl_;
  if (with_articulations) {
    auto solver = std::make_unique<SequentialImpulseSolver<RotorContactSolver>>();
    auto world = std::make_unique<ArticulatedDynamicsWorld>(
        &i.dispatcher, &i.broadphase, solver.get(), &i.collision_config, &i.soft_solver);
    i.soft_multibody = world.get();
    i.solver = std::move(solver);
    i.world = std::move(world);
  } else {
    i.solver = std::make_unique<SequentialImpulseSolver<btSequentialImpulseConstraintSolver>>();
    auto world = std::make_unique<DynamicsWorld<btSoftRigidDynamicsWorld>>(
        &i.dispatcher, &i.broadphase, i.solver.get(), &i.collision_config, &i.soft_solver);
    i.soft_rigid = world.get();
    i.world = std::move(world);
  }
}

BulletWorld::~BulletWorld() {
  impl_->world.reset();  // before the solver it uses
}

btDiscreteDynamicsWorld& BulletWorld::dynamics() {
  return *impl_->world;
}

btCollisionDispatcher& BulletWorld::dispatcher() {
  return impl_->dispatcher;
}

const btCollisionDispatcher& BulletWorld::dispatcher() const {
  return impl_->dispatcher;
}

btSoftBodyWorldInfo& BulletWorld::softBodyInfo() {
  return impl_->soft_rigid ? impl_->soft_rigid->getWorldInfo()
                           : impl_->soft_multibody->getWorldInfo();
}

void BulletWorld::addSoftBody(btSoftBody& body, std::optional<int> coulomb_substeps,
                              const std::optional<SoftMaterial>& material) {
  if (coulomb_substeps) impl_->soft_solver.useCoulombContacts(body, *coulomb_substeps, material);
  if (impl_->soft_rigid) {
    impl_->soft_rigid->addSoftBody(&body);
  } else {
    impl_->soft_multibody->addSoftBody(&body);
  }
}

void BulletWorld::removeSoftBody(btSoftBody& body) {
  impl_->soft_solver.forget(body);
  if (impl_->soft_rigid) {
    impl_->soft_rigid->removeSoftBody(&body);
  } else {
    impl_->soft_multibody->removeSoftBody(&body);
  }
}

const std::vector<NodeContactImpulse>& BulletWorld::coulombImpulses() const {
  return impl_->soft_solver.lastImpulses();
}

SoftBodyStepSolver& BulletWorld::softBodySolver() {
  return impl_->soft_solver;
}

ElasticSolveStats BulletWorld::elasticStats(const btSoftBody& body) const {
  return impl_->soft_solver.elasticStats(body);
}

btMultiBodyDynamicsWorld& BulletWorld::articulations() {
  if (!impl_->soft_multibody) throw std::logic_error("this Bullet world has no articulations");
  return *impl_->soft_multibody;
}

void BulletWorld::setFreeMotionListener(std::function<void()> listener) {
  articulations();  // throws without them
  impl_->soft_multibody->setFreeMotionListener(std::move(listener));
}

void keepBroadphaseBalanced(btCollisionWorld& world) {
  // Every world here is built on a btDbvtBroadphase (BulletWorld::Impl).
  auto& broadphase = static_cast<btDbvtBroadphase&>(*world.getBroadphase());
  const int proxies = broadphase.m_sets[0].m_leaves + broadphase.m_sets[1].m_leaves;
  // Between two rebuilds at most this many proxies hang off one another: n/1024 rebuilds of
  // n log n each, against n^2/2 steps down an unbalanced tree.
  constexpr int kRebuildEvery = 1024;
  if (proxies % kRebuildEvery == 0) broadphase.optimize();
}

}  // namespace ambf_like::detail
