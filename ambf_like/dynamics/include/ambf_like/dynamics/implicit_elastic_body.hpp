#pragma once
// A soft body with a material, stepped by backward Euler with Coulomb contacts and pins.

#include <BulletSoftBody/btSoftBody.h>

#include <Eigen/Core>
#include <unordered_map>
#include <vector>

#include "ambf_like/dynamics/corotated_tets.hpp"
#include "ambf_like/dynamics/elastic_contacts.hpp"
#include "ambf_like/dynamics/node_block_cholesky.hpp"

namespace ambf_like::detail {

/// How one step of an elastic body went: what its solve took and what energy it left.
struct ElasticStepReport {
  int iterations = 0;       ///< solves of the system (1: the linearly implicit step was kept)
  int halvings = 0;         ///< of the line search, over all iterations
  bool energy_kept = true;  ///< the step gained no energy beyond its tolerance
};

/// Steps a soft body's nodes as a corotated solid of its material by backward Euler: the end
/// of step minimises the incremental potential
///   Phi(v) = 1/2 |v - v0|_M^2 - h f_ext . v + Psi(x0 + h v)
/// subject to its contacts and pins. Its quasi-Newton iteration takes the matrix
/// A = M + h^2 K, K the stiffness at rest turned by the body's overall rotation, factored once
/// per step size (every iteration costs one solve, whatever the material's stiffness), and
/// solves the contacts and pins with that same matrix in each iteration (each node's velocity
/// answers an impulse on any contact node through the inverse's 3x3 blocks).
///
/// Its first iteration from v = 0 is linearly implicit Euler, (M + h^2 K) v' = M v0 +
/// h (f(x0) + f_ext) + contact impulses. That step is kept when it gains no mechanical energy
/// beyond the work of its contacts and pins (the balance backward Euler itself keeps: it
/// loses 1/2 |v' - v0|_M^2 and more); otherwise the iteration goes on, each step along the
/// solve's direction cut back (halved) until Phi, with the impulses as fixed forces, falls by a
/// share of what the solve promised (Armijo), until the balance holds or the step stops
/// moving. A body bent or crushed far from the matrix's linearisation therefore takes more
/// iterations instead of gaining energy. At rest (v' = v0 = 0) the contacts carry exactly
/// f(x) + f_ext, the material's answer to the deformation, whatever the step.
class ImplicitElasticBody {
 public:
  /// `body`'s nodes as they are now are its rest shape; nodes of no mass stay where they are.
  ImplicitElasticBody(const btSoftBody& body, const SoftMaterial& material);

  /// One step of `h` from the nodes' positions (m_x) and velocities (m_v): their new velocities
  /// in m_v and positions in m_x (the start kept in m_q). `acceleration` per node is the
  /// external forces' (gravity); `contacts` (contacts and pins) get their impulses.
  ElasticStepReport step(btSoftBody& body, double h, const std::vector<btVector3>& acceleration,
                         std::vector<ElasticContact>& contacts);

 private:
  /// The elastic forces and energy at a set of positions.
  struct Elastic {
    Eigen::VectorXd positions;
    Eigen::VectorXd forces;
    double energy = 0.0;
  };

  void factor(double h);
  const NodeResponse& responseTo(int node);
  /// Follows the body's overall rotation (the polar rotation of its mass-weighted spread).
  void followBodyRotation(const Eigen::VectorXd& positions);
  /// The forces and energy at `at.positions`, the body's rotation followed there.
  void evaluate(Elastic& at);
  /// Reads the nodes' positions and velocities and their weights under `acceleration` into
  /// start_, start_velocity_ and weight_, and the elastic state there into last_.
  void loadNodes(const btSoftBody& body, const std::vector<btVector3>& acceleration);
  /// Writes the step's end (last_'s positions, `velocity`) to the nodes, less the motion out of
  /// a surface a node began inside.
  void storeNodes(btSoftBody& body, double h, const std::vector<ElasticContact>& contacts,
                  Eigen::VectorXd& velocity) const;
  /// The change of velocity one solve from `velocity` (zero when `from_rest`) makes, with
  /// `residual` the forces' and inertia's imbalance there (solved in the rest frame): A^-1
  /// residual, then the contacts' and pins' impulses on the velocity it reaches.
  void solveFrom(const Eigen::VectorXd& velocity, bool from_rest, const Eigen::VectorXd& residual,
                 std::vector<ElasticContact>& contacts, Eigen::VectorXd& direction);

  CorotatedTets tets_;
  Eigen::VectorXd mass_;   ///< per coordinate; 0 for a node that stays put
  Eigen::VectorXd moves_;  ///< per coordinate: 1, or 0 for a node that stays put
  /// Each node's rest offset from the rest centre of mass times its mass (3 x nodes; empty when
  /// no node has mass).
  Eigen::Matrix3Xd weighted_rest_;
  double mean_edge_ = 0.0;  ///< of the rest tetrahedra (m)
  Rotation body_rotation_;
  double factored_step_ = 0.0;
  NodeBlockCholesky system_;
  std::unordered_map<int, NodeResponse> responses_;  ///< by node, for the factored step
  ElasticContactSolver contact_solver_;
  Elastic last_;  ///< at the end of the last step: the next one starts from it if nothing moved
  Elastic trial_;
  /// A step's working vectors (3 entries per node), kept to spare their allocations.
  Eigen::VectorXd start_, start_velocity_, weight_, velocity_, direction_, residual_,
      free_velocity_;
  std::unordered_map<int, Eigen::Vector3d> pushed_;  ///< impulses by node, in a solve
};

}  // namespace ambf_like::detail
