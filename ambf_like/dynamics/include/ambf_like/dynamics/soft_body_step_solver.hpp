#pragma once
// The soft bodies' step: Bullet's default solver, with substeps, Coulomb contacts and an implicit
// elastic solve for the soft bodies that ask for them.

#include <BulletSoftBody/btDefaultSoftBodySolver.h>

#include <map>
#include <memory>
#include <optional>
#include <unordered_map>
#include <utility>
#include <vector>

#include "ambf_like/dynamics/implicit_elastic_body.hpp"
#include "ambf_like/dynamics/packed_link_solver.hpp"
#include "ambf_like/elastic_solve_stats.hpp"

class btCollisionObject;

namespace ambf_like::detail {

/// How much farther than its margin (m) an elastic body's node is taken as a contact: Bullet finds
/// a body's contacts once per step, and a node that is not one when the step begins passes
/// through a rigid surface unopposed if it reaches it during the step (an elastic solid's nodes
/// move that far within a step when it is squeezed). The contact plane stays at the margin.
constexpr double kCoulombContactBand = 0.001;

/// The impulse one soft-body node exchanged with a rigid body in the last step.
struct NodeContactImpulse {
  const btSoftBody* soft = nullptr;
  const btCollisionObject* rigid = nullptr;
  btVector3 position;  ///< the node, after the step
  btVector3 normal;    ///< the rigid surface's normal, pointing to the node
  btVector3 normal_impulse;
  btVector3 friction_impulse;  ///< on the node, tangential
};

/// btDefaultSoftBodySolver that, for the soft bodies registered with it, replaces Bullet's
/// rigid-contact projection (ePSolver::RContacts: a node within the margin sticks whenever
/// kDF x friction >= 1, however lightly it is pressed) by Coulomb contacts, and splits the
/// body's step into substeps.
///
/// Each substep integrates the nodes over its share of the step (Bullet's forces and pose
/// matching as it predicted them for the whole step) and iterates the body's own constraints
/// (links, anchors). Then every node found inside a rigid body (the contact plane moved with the
/// body) is pushed back onto its surface: the normal impulse J_n = m dx / h_sub its elasticity
/// and motion pressed it in with. Its slip along the surface over the substep, relative to the
/// surface's own motion, is undone if that takes no more than mu J_n (stick), else reduced by
/// mu J_n (slip), mu = kDF x the rigid body's friction. After the step the opposite impulses go
/// to the rigid bodies: a grasp is held, and felt, by its squeeze and nothing else.
///
/// A body with a material has no links in its solve: each substep is one implicit step of its
/// tetrahedra (ImplicitElasticBody), which solves its Coulomb contacts and its anchors (as pins)
/// with the same matrix.
///
/// Why substeps: a position-based body presses back on what squeezes it with about
/// m x dx / h^2, so with n substeps n^2 times harder, at the cost of n passes over its
/// constraints (Macklin et al. 2019, "Small steps in physics simulation"). Without them a
/// squeezed ring's push, and so its grip, is a few hundredths of a newton. Bullet's drift
/// iterations (diterations) are not run for these bodies.
///
/// Every other body gets Bullet's own solve, on packed arrays when its step is only links
/// (PackedLinkSolver).
class SoftBodyStepSolver final : public btDefaultSoftBodySolver {
 public:
  /// `body` gets Coulomb contacts and `substeps` (>= 1) substeps of `piterations` iterations;
  /// Bullet's own rigid-contact projection is taken out of it. With a `material`, its
  /// tetrahedra replace its links.
  void useCoulombContacts(btSoftBody& body, int substeps,
                          const std::optional<SoftMaterial>& material);
  void forget(const btSoftBody& body);
  /// Bullet's prediction, keeping only the face trees something reads (soft_body_upkeep.hpp).
  void predictMotion(btScalar solver_dt) override;
  void solveConstraints(btScalar solver_dt) override;
  /// Bullet's end of step (btSoftBody::integrateMotion) for the bodies whose normals the step
  /// reads (normalsAreRead): it only recomputes the nodes' and faces' normals (5 % of the
  /// peg-transfer scene's step, 11 % of AMBF's cloth's).
  void updateSoftBodies() override;
  /// The Coulomb contacts' impulses of the last step.
  const std::vector<NodeContactImpulse>& lastImpulses() const { return impulses_; }
  /// Its implicit steps so far; zeros for a body without a material.
  ElasticSolveStats elasticStats(const btSoftBody& body) const;

  /// What the next steps depend on: per registered body its warm starts and its elastic
  /// solver's state, and the last step's impulses (World::saveState).
  struct State;
  std::shared_ptr<const State> state() const;
  /// Restores a state of this solver with the same bodies registered.
  void restore(const State& state);

 private:
  /// A registered body: its substeps, its elasticity if it has a material (with its contacts'
  /// last impulses, by node and surface), and its nodes' velocities before Bullet's prediction.
  struct Registered {
    int substeps = 1;
    std::optional<ImplicitElasticBody> elasticity;
    std::map<std::pair<int, const btCollisionObject*>, Eigen::Vector3d> last_impulse;
    /// Its pins' (anchors') last impulses, by node and rigid body.
    std::map<std::pair<int, const btCollisionObject*>, Eigen::Vector3d> last_pin_impulse;
    std::vector<btVector3> start_velocity;
    ElasticSolveStats stats;
  };
  /// One node-rigid contact over a step.
  struct Accumulated {
    btVector3 surface_velocity{0, 0, 0};  ///< of the rigid surface at the node
    bool placed = false;         ///< a kinematic body's: its plane does not move during the step
    bool fixed = true;           ///< a surface nothing moves (a static object, a fixed base)
    btVector3 impulse{0, 0, 0};  ///< on the node, over the step so far (N s)
    btVector3 normal_impulse{0, 0, 0};  ///< its part along the normal
  };

  void solve(btSoftBody& body, Registered& registered);
  /// Bullet's own constraint pass without its position and drift iterations.
  static void prepareWithBullet(btSoftBody& body);
  /// Keeps Bullet's predicted acceleration and pose pull per node; puts the nodes back at the
  /// step's start.
  void rewindPrediction(btSoftBody& body, const Registered& registered, int substeps);
  /// One substep of `hs`, ending `elapsed` into the step: integrate, iterate, contacts.
  void substep(btSoftBody& body, btScalar hs, btScalar elapsed);
  /// One implicit substep of a body with a material, its contacts solved with it.
  void elasticSubstep(btSoftBody& body, Registered& registered, btScalar hs, btScalar elapsed);
  /// An anchor of a body with a material as a pin of its step: the node ends the substep
  /// `elapsed` into the step (of `hs`) on the anchor's point of its rigid body.
  ElasticContact pinOf(const btSoftBody& body, const btSoftBody::Anchor& anchor, btScalar hs,
                       btScalar elapsed) const;
  /// Bullet's position solvers left in the body's sequence (anchors, soft contacts), once.
  static void runBulletSolvers(btSoftBody& body);
  /// Damping, the step's start back in m_q, forces cleared.
  void finishStep(btSoftBody& body);
  /// The surfaces' velocities; for an `elastic` body each contact plane moved from the
  /// detection band back to the margin.
  void startContacts(btSoftBody& body, bool elastic);
  /// How far along its normal a contact's surface has moved `elapsed` into the step.
  btScalar surfaceAdvance(const btSoftBody::RContact& contact, std::size_t index,
                          btScalar elapsed) const;
  /// A substep's contacts, the rigid surfaces where they are `elapsed` into the step.
  void projectContacts(btSoftBody& body, btScalar elapsed);
  void applyToRigidBodies(const btSoftBody& body);

  std::unordered_map<const btSoftBody*, Registered> coulomb_;
  std::vector<Accumulated> contacts_;    ///< of the body being solved, by m_rcontacts index
  std::vector<btVector3> pin_impulses_;  ///< on its nodes over the step, by m_anchors index
  btScalar step_size_ = 0;               ///< of the step being solved
  std::vector<btVector3> acceleration_, pose_pull_, step_start_;  ///< scratch, per node
  std::vector<NodeContactImpulse> impulses_;
  PackedLinkSolver packed_links_;  ///< the other bodies' steps that are links alone
};

}  // namespace ambf_like::detail
