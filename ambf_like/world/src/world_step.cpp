// One step of the world, written as its stages in the order they run.

#include <BulletSoftBody/btSoftBody.h>

#include "world_impl.hpp"

namespace ambf_like {

void World::step() {
  const double h = impl_->options.step_size;
  auto& stage = *impl_;
  stage.driveJoints(h);
  stage.loadArticulations(h);
  stage.wakeOrSleepSoftBodies();
  stage.advanceBullet(h);
  stage.readArticulations();
  stage.castSensors();
  stage.putRestedSoftBodiesToSleep(h);
  stage.readJointCoordinates();
  stage.collectSdfCells();
  stage.advanceClock(h);
  stage.guardAgainstDivergence();
}

/// Each joint's controller (PID, servo, actuator) turns its command into this step's effort or
/// motor target.
void World::Impl::driveJoints(double h) {
  for (auto& j : joints) j->joint->applyControl(h);
}

/// Reduced-coordinate trees take those efforts as their joints' torques for the step; stops on
/// sums of their coordinates join the solve when near their bound.
void World::Impl::loadArticulations(double h) {
  for (auto& a : articulations) a->beforeStep(h);
  for (auto& stop : coupled_stops) stop->watch(h);
}

/// Sleeping soft bodies that something moving approaches, or an anchor holds, wake and rejoin
/// Bullet's step (SoftBodySleeper).
void World::Impl::wakeOrSleepSoftBodies() {
  if (sleeper) sleeper->beforeStep(soft_bodies, bodies);
}

/// Bullet's single step (btSoftMultiBodyDynamicsWorld / btSoftRigidDynamicsWorld), in order:
///  1. predict motion: rigid bodies and articulations under gravity and efforts; soft bodies'
///     forces and pose matching (SoftBodyStepSolver::predictMotion);
///  2. predictive contacts: only while some body asks for CCD (DynamicsWorld);
///  3. collision detection: broadphase, then narrowphase manifolds;
///  4. islands;
///  5. constraints: the free motion is applied to the articulations first, and their servos told
///     (ArticulatedDynamicsWorld), then contacts, joints and limits by sequential impulses;
///  6. integrate the rigid bodies and articulations;
///  7. soft bodies: substeps, Coulomb contacts, elastic solve, or Bullet's own solve
///     (SoftBodyStepSolver);
///  8. soft bodies' normals, only where something reads them.
void World::Impl::advanceBullet(double h) {
  world.stepSimulation(h, 0, h);
}

/// The articulations' link bodies take their links' new poses and velocities.
void World::Impl::readArticulations() {
  for (auto& a : articulations) a->afterStep();
}

/// Proximity sensors cast their rays against the new poses.
void World::Impl::castSensors() {
  for (auto& s : sensors) {
    if (s->active()) s->sense(world);
  }
}

/// Soft bodies that have rested long enough go to sleep: Bullet's soft-body solver skips them.
void World::Impl::putRestedSoftBodiesToSleep(double h) {
  if (sleeper) sleeper->afterStep(soft_bodies, h);
}

/// Each joint's position and velocity, as its command interface reads them.
void World::Impl::readJointCoordinates() {
  for (auto& j : joints) j->joint->updateCoordinate();
}

/// The sparse SDF frees the cells unused for a number of collections; a collection walks every
/// hash bucket (1.4 % of the peg-transfer scene's step when run every 64 steps), so it runs every
/// 256 steps and frees cells unused for 64 of them: 16k steps. With no cell at all (no soft body
/// has met a rigid one) there is nothing to walk for.
void World::Impl::collectSdfCells() {
  if (soft_bodies.empty() || steps % 256 != 0) return;
  auto& sdf = bullet.softBodyInfo().m_sparsesdf;
  if (sdf.ncells > 0) sdf.GarbageCollect(64);
}

/// The simulated time is the step count times the step: no rounding drift over long runs.
void World::Impl::advanceClock(double h) {
  ++steps;
  time = static_cast<double>(steps) * h;
}

/// Throws SimulationDiverged when a body or node is not finite, has left the world or moves
/// faster than the scene allows (StepGuard).
void World::Impl::guardAgainstDivergence() {
  guard->check(bodies, soft_bodies, steps, time);
}

}  // namespace ambf_like
