#include "ambf_like/dynamics/soft_body_step_solver.hpp"

#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <BulletSoftBody/btSoftBody.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "ambf_like/bullet_conversions.hpp"
#include "ambf_like/dynamics/link_point.hpp"
#include "ambf_like/dynamics/soft_body_upkeep.hpp"

namespace ambf_like::detail {

namespace {

/// The rigid body a node touches, or null for a static object or an articulation's link (see
/// movingLink).
btRigidBody* movingRigidBody(const btCollisionObject* object) {
  auto* rigid = const_cast<btRigidBody*>(btRigidBody::upcast(object));
  return rigid != nullptr && rigid->getInvMass() > 0.0 ? rigid : nullptr;
}

bool isCoulombContact(const btSoftBody::RContact& contact) {
  return contact.m_node->m_im > 0.0 && contact.m_cti.m_colObj->hasContactResponse();
}

}  // namespace

void SoftBodyStepSolver::useCoulombContacts(btSoftBody& body, int substeps,
                                            const std::optional<SoftMaterial>& material) {
  auto& sequence = body.m_cfg.m_psequence;
  for (int i = sequence.size() - 1; i >= 0; --i) {
    // A body with a material solves its links' work and its anchors (as pins) in its step.
    const bool replaced = sequence[i] == btSoftBody::ePSolver::RContacts ||
                          (material && (sequence[i] == btSoftBody::ePSolver::Linear ||
                                        sequence[i] == btSoftBody::ePSolver::Anchors));
    if (replaced) sequence.removeAtIndex(i);
  }
  Registered& registered = coulomb_[&body];
  registered.substeps = substeps;
  if (material) registered.elasticity.emplace(body, *material);
}

ElasticSolveStats SoftBodyStepSolver::elasticStats(const btSoftBody& body) const {
  const auto it = coulomb_.find(&body);
  return it == coulomb_.end() ? ElasticSolveStats{} : it->second.stats;
}

struct SoftBodyStepSolver::State {
  std::unordered_map<const btSoftBody*, Registered> bodies;
  std::vector<NodeContactImpulse> impulses;
};

std::shared_ptr<const SoftBodyStepSolver::State> SoftBodyStepSolver::state() const {
  return std::make_shared<const State>(State{coulomb_, impulses_});
}

void SoftBodyStepSolver::restore(const State& state) {
  const auto same_body = [&](const auto& entry) {
    const auto it = state.bodies.find(entry.first);
    return it != state.bodies.end() &&
           it->second.elasticity.has_value() == entry.second.elasticity.has_value();
  };
  if (state.bodies.size() != coulomb_.size() ||
      !std::all_of(coulomb_.begin(), coulomb_.end(), same_body)) {
    throw std::logic_error("a soft-body solver state of other bodies");
  }
  for (auto& [body, registered] : coulomb_) registered = state.bodies.at(body);
  impulses_ = state.impulses;
  packed_links_.forgetAll();  // the restored links' constants may be others
}

void SoftBodyStepSolver::forget(const btSoftBody& body) {
  coulomb_.erase(&body);
  packed_links_.forget(body);
}

void SoftBodyStepSolver::predictMotion(btScalar solver_dt) {
  for (auto& [body, registered] : coulomb_) {
    if (!body->isActive()) continue;
    registered.start_velocity.resize(static_cast<std::size_t>(body->m_nodes.size()));
    for (int i = 0; i < body->m_nodes.size(); ++i) {
      registered.start_velocity[static_cast<std::size_t>(i)] = body->m_nodes[i].m_v;
    }
  }
  for (int i = 0; i < m_softBodySet.size(); ++i) {
    // Bullet refreshes the links' constants in this prediction.
    if (m_softBodySet[i]->m_bUpdateRtCst) packed_links_.forget(*m_softBodySet[i]);
  }
  rebuildReadableFaceTrees(m_softBodySet);
  btDefaultSoftBodySolver::predictMotion(solver_dt);
  emptyUnreadFaceTrees(m_softBodySet);
}

void SoftBodyStepSolver::solveConstraints(btScalar /*solver_dt*/) {
  impulses_.clear();
  for (int i = 0; i < m_softBodySet.size(); ++i) {
    btSoftBody& body = *m_softBodySet[i];
    if (!body.isActive()) continue;
    if (auto it = coulomb_.find(&body); it != coulomb_.end()) {
      solve(body, it->second);
    } else if (PackedLinkSolver::handles(body)) {
      packed_links_.solve(body);
    } else {
      body.solveConstraints();
    }
  }
}

void SoftBodyStepSolver::updateSoftBodies() {
  for (int i = 0; i < m_softBodySet.size(); ++i) {
    btSoftBody& body = *m_softBodySet[i];
    if (body.isActive() && normalsAreRead(body)) body.integrateMotion();
  }
}

void SoftBodyStepSolver::solve(btSoftBody& body, Registered& registered) {
  prepareWithBullet(body);
  const btScalar h = body.m_sst.sdt;
  step_size_ = h;
  const int substeps = registered.substeps;
  const btScalar hs = h / substeps;
  rewindPrediction(body, registered, substeps);
  startContacts(body, registered.elasticity.has_value());
  body.m_sst.sdt = hs;
  body.m_sst.isdt = 1.0 / hs;
  for (int s = 0; s < substeps; ++s) {
    if (registered.elasticity) {
      elasticSubstep(body, registered, hs, (s + 1) * hs);
    } else {
      substep(body, hs, (s + 1) * hs);
    }
  }
  body.m_sst.sdt = h;
  body.m_sst.isdt = 1.0 / h;
  finishStep(body);
  applyToRigidBodies(body);
}

void SoftBodyStepSolver::prepareWithBullet(btSoftBody& body) {
  // Bullet prepares links and anchors and runs any velocity iterations; the position
  // iterations and the contacts are left to the substeps. What it prepares of a link is read
  // by its velocity iterations only: without those, anchors or clusters it does nothing used.
  auto& cfg = body.m_cfg;
  if (cfg.viterations <= 0 && body.m_anchors.size() == 0 && body.m_clusters.size() == 0) return;
  const int iterations = cfg.piterations;
  const int drift_iterations = cfg.diterations;
  cfg.piterations = 0;
  cfg.diterations = 0;
  body.solveConstraints();
  cfg.piterations = iterations;
  cfg.diterations = drift_iterations;
}

void SoftBodyStepSolver::rewindPrediction(btSoftBody& body, const Registered& registered,
                                          int substeps) {
  // Bullet predicted x = lerp(q + (v0 + a h) h, pose goal, kMT) for the whole step: keep its
  // acceleration and its pose-matching pull, and go back to the step's start.
  const auto count = static_cast<std::size_t>(body.m_nodes.size());
  const btScalar h = body.m_sst.sdt;
  acceleration_.resize(count);
  pose_pull_.resize(count);
  step_start_.resize(count);
  const bool known_start = registered.start_velocity.size() == count;
  for (std::size_t k = 0; k < count; ++k) {
    btSoftBody::Node& n = body.m_nodes[static_cast<int>(k)];
    const btVector3 v0 = known_start ? registered.start_velocity[k] : n.m_v;
    acceleration_[k] = (n.m_v - v0) / h;
    pose_pull_[k] = (n.m_x - (n.m_q + n.m_v * h)) / substeps;
    step_start_[k] = n.m_q;
    n.m_x = n.m_q;
    n.m_v = v0;
  }
}

void SoftBodyStepSolver::substep(btSoftBody& body, btScalar hs, btScalar elapsed) {
  for (std::size_t k = 0; k < acceleration_.size(); ++k) {
    btSoftBody::Node& n = body.m_nodes[static_cast<int>(k)];
    n.m_q = n.m_x;
    n.m_v += acceleration_[k] * hs;
    n.m_x += n.m_v * hs + pose_pull_[k];
  }
  const auto& cfg = body.m_cfg;
  for (int k = 0; k < cfg.piterations; ++k) {
    const btScalar ti = k / static_cast<btScalar>(cfg.piterations);
    for (int q = 0; q < cfg.m_psequence.size(); ++q) {
      btSoftBody::getSolver(cfg.m_psequence[q])(&body, 1.0, ti);
    }
  }
  projectContacts(body, elapsed);
  for (int i = 0; i < body.m_nodes.size(); ++i) {
    btSoftBody::Node& n = body.m_nodes[i];
    n.m_v = (n.m_x - n.m_q) / hs;
  }
}

void SoftBodyStepSolver::elasticSubstep(btSoftBody& body, Registered& registered, btScalar hs,
                                        btScalar elapsed) {
  std::vector<ElasticContact> contacts;
  std::vector<std::size_t> source;  // each one's index in m_rcontacts
  const btScalar kdf = body.m_cfg.kDF;
  for (int i = 0; i < body.m_rcontacts.size(); ++i) {
    const btSoftBody::RContact& rc = body.m_rcontacts[i];
    if (!isCoulombContact(rc)) continue;
    const auto index = static_cast<std::size_t>(i);
    const btVector3& n = rc.m_cti.m_normal;
    const btVector3& x = rc.m_node->m_x;
    ElasticContact c;
    c.node = static_cast<int>(rc.m_node - &body.m_nodes[0]);
    c.normal = toEigen(n);
    c.surface_velocity = toEigen(contacts_[index].surface_velocity);
    const btScalar gap_at_end = n.dot(x) + rc.m_cti.m_offset - surfaceAdvance(rc, index, elapsed);
    c.least_normal_velocity = -gap_at_end / hs;
    c.start_depth = -(n.dot(x) + rc.m_cti.m_offset - surfaceAdvance(rc, index, elapsed - hs));
    c.friction = kdf * rc.m_cti.m_colObj->getFriction();
    c.fixed_surface = contacts_[index].fixed;
    if (const auto last = registered.last_impulse.find({c.node, rc.m_cti.m_colObj});
        last != registered.last_impulse.end()) {
      c.impulse = last->second;
    }
    contacts.push_back(c);
    source.push_back(index);
  }
  const std::size_t first_pin = contacts.size();
  for (int a = 0; a < body.m_anchors.size(); ++a) {
    const btSoftBody::Anchor& anchor = body.m_anchors[a];
    contacts.push_back(pinOf(body, anchor, hs, elapsed));
    if (const auto last = registered.last_pin_impulse.find({contacts.back().node, anchor.m_body});
        last != registered.last_pin_impulse.end()) {
      contacts.back().impulse = last->second;
    }
  }
  const ElasticStepReport report = registered.elasticity->step(body, hs, acceleration_, contacts);
  ElasticSolveStats& stats = registered.stats;
  ++stats.steps;
  stats.iterations += static_cast<std::uint64_t>(report.iterations);
  stats.halvings += static_cast<std::uint64_t>(report.halvings);
  stats.energy_gaining += report.energy_kept ? 0 : 1;
  registered.last_pin_impulse.clear();
  for (int a = 0; a < body.m_anchors.size(); ++a) {
    const ElasticContact& pin = contacts[first_pin + static_cast<std::size_t>(a)];
    registered.last_pin_impulse[{pin.node, body.m_anchors[a].m_body}] = pin.impulse;
    pin_impulses_[static_cast<std::size_t>(a)] += toBt(pin.impulse);
  }
  contacts.resize(first_pin);
  runBulletSolvers(body);
  registered.last_impulse.clear();
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    const ElasticContact& c = contacts[k];
    const btSoftBody::RContact& rc = body.m_rcontacts[static_cast<int>(source[k])];
    registered.last_impulse[{c.node, rc.m_cti.m_colObj}] = c.impulse;
    const btVector3 impulse = toBt(c.impulse);
    Accumulated& state = contacts_[source[k]];
    state.impulse += impulse;
    state.normal_impulse += rc.m_cti.m_normal * rc.m_cti.m_normal.dot(impulse);
  }
}

ElasticContact SoftBodyStepSolver::pinOf(const btSoftBody& body, const btSoftBody::Anchor& anchor,
                                         btScalar hs, btScalar elapsed) const {
  // The rigid body has been moved to the step's end: its point `h - elapsed` earlier is where
  // the pin is `elapsed` into the step.
  const btVector3 arm = anchor.m_body->getWorldTransform().getBasis() * anchor.m_local;
  const btVector3 point_velocity = anchor.m_body->getVelocityInLocalPoint(arm);
  const btVector3 point = anchor.m_body->getWorldTransform().getOrigin() + arm -
                          point_velocity * (step_size_ - elapsed);
  ElasticContact pin;
  pin.node = static_cast<int>(anchor.m_node - &body.m_nodes[0]);
  pin.pinned = true;
  pin.surface_velocity = toEigen((point - anchor.m_node->m_x) / hs);
  return pin;
}

void SoftBodyStepSolver::runBulletSolvers(btSoftBody& body) {
  const auto& sequence = body.m_cfg.m_psequence;
  if (sequence.size() == 0) return;
  for (int q = 0; q < sequence.size(); ++q) btSoftBody::getSolver(sequence[q])(&body, 1.0, 0.0);
  const btScalar hs = body.m_sst.sdt;
  for (int i = 0; i < body.m_nodes.size(); ++i) {
    btSoftBody::Node& n = body.m_nodes[i];
    n.m_v = (n.m_x - n.m_q) / hs;
  }
}

void SoftBodyStepSolver::finishStep(btSoftBody& body) {
  for (std::size_t k = 0; k < step_start_.size(); ++k) {
    btSoftBody::Node& n = body.m_nodes[static_cast<int>(k)];
    n.m_v *= 1.0 - body.m_cfg.kDP;  // Bullet's damping, once per step
    n.m_q = step_start_[k];
    n.m_f.setZero();
  }
}

void SoftBodyStepSolver::startContacts(btSoftBody& body, bool elastic) {
  contacts_.assign(static_cast<std::size_t>(body.m_rcontacts.size()), Accumulated{});
  pin_impulses_.assign(static_cast<std::size_t>(body.m_anchors.size()), btVector3(0, 0, 0));
  for (int i = 0; i < body.m_rcontacts.size(); ++i) {
    btSoftBody::RContact& contact = body.m_rcontacts[i];
    if (elastic) contact.m_cti.m_offset += kCoulombContactBand;
    const btVector3 arm =
        contact.m_node->m_x - contact.m_cti.m_colObj->getWorldTransform().getOrigin();
    Accumulated& state = contacts_[static_cast<std::size_t>(i)];
    if (const btRigidBody* rigid = movingRigidBody(contact.m_cti.m_colObj)) {
      state.surface_velocity = rigid->getVelocityInLocalPoint(arm);
      state.fixed = false;
    } else if (const auto* link = movingLink(contact.m_cti.m_colObj)) {
      state.surface_velocity = linkPointVelocity(*link, contact.m_node->m_x);
      state.fixed = false;
    } else if (const btRigidBody* kinematic = btRigidBody::upcast(contact.m_cti.m_colObj);
               kinematic != nullptr && kinematic->isKinematicObject()) {
      // Placed by its owner before the step, so its contact plane is already where the step
      // ends; its motion (Bullet's, from the last two placements) still drags what it touches.
      state.surface_velocity = kinematic->getVelocityInLocalPoint(arm);
      state.placed = true;
      state.fixed = false;
    }
  }
}

btScalar SoftBodyStepSolver::surfaceAdvance(const btSoftBody::RContact& contact, std::size_t index,
                                            btScalar elapsed) const {
  const Accumulated& state = contacts_[index];
  return state.placed ? 0.0 : contact.m_cti.m_normal.dot(state.surface_velocity) * elapsed;
}

void SoftBodyStepSolver::projectContacts(btSoftBody& body, btScalar elapsed) {
  const btScalar kdf = body.m_cfg.kDF;
  const btScalar hs = body.m_sst.sdt;
  for (int i = 0; i < body.m_rcontacts.size(); ++i) {
    const btSoftBody::RContact& contact = body.m_rcontacts[i];
    if (!isCoulombContact(contact)) continue;
    btSoftBody::Node& node = *contact.m_node;
    const auto index = static_cast<std::size_t>(i);
    Accumulated& state = contacts_[index];
    const btVector3& normal = contact.m_cti.m_normal;
    // The contact plane was found where the rigid body was when the step began: move it along.
    const btScalar depth =
        -(normal.dot(node.m_x) + contact.m_cti.m_offset - surfaceAdvance(contact, index, elapsed));
    if (depth <= 0.0) continue;
    node.m_x += normal * depth;
    // Slip over the substep, relative to the surface: undone within mu x the normal push.
    const btVector3 relative = node.m_x - node.m_q - state.surface_velocity * hs;
    btVector3 friction = -(relative - normal * normal.dot(relative));
    const btScalar limit = kdf * contact.m_cti.m_colObj->getFriction() * depth;
    const btScalar size = friction.length();
    if (size > limit) friction *= limit / size;
    node.m_x += friction;
    const btScalar mass_rate = 1.0 / (node.m_im * hs);  // impulse per unit of correction
    const btVector3 normal_impulse = normal * (depth * mass_rate);
    state.normal_impulse += normal_impulse;
    state.impulse += normal_impulse + friction * mass_rate;
  }
}

void SoftBodyStepSolver::applyToRigidBodies(const btSoftBody& body) {
  if (coulomb_.at(&body).elasticity) {
    for (int a = 0; a < body.m_anchors.size(); ++a) {
      const btSoftBody::Anchor& anchor = body.m_anchors[a];
      btRigidBody* rigid = movingRigidBody(anchor.m_body);
      if (rigid == nullptr) continue;
      rigid->applyImpulse(-pin_impulses_[static_cast<std::size_t>(a)],
                          anchor.m_node->m_x - rigid->getWorldTransform().getOrigin());
    }
  }
  for (int i = 0; i < body.m_rcontacts.size(); ++i) {
    const btSoftBody::RContact& contact = body.m_rcontacts[i];
    const Accumulated& state = contacts_[static_cast<std::size_t>(i)];
    if (state.impulse.isZero()) continue;
    const btSoftBody::Node& node = *contact.m_node;
    if (btRigidBody* rigid = movingRigidBody(contact.m_cti.m_colObj)) {
      rigid->applyImpulse(-state.impulse, node.m_x - rigid->getWorldTransform().getOrigin());
    } else if (auto* link = movingLink(contact.m_cti.m_colObj)) {
      applyLinkImpulse(*link, node.m_x, -state.impulse);
    }
    impulses_.push_back({&body, contact.m_cti.m_colObj, node.m_x, contact.m_cti.m_normal,
                         state.normal_impulse, state.impulse - state.normal_impulse});
  }
}

}  // namespace ambf_like::detail
