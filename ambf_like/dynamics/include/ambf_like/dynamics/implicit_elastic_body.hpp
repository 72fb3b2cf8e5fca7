#pragma once
// A soft body with a material, stepped by linearly implicit Euler with Coulomb contacts.

#include <BulletSoftBody/btSoftBody.h>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <unordered_map>
#include <vector>

#include "ambf_like/dynamics/corotated_tets.hpp"
#include "ambf_like/dynamics/node_block_cholesky.hpp"

namespace ambf_like::detail {

/// One node of an elastic body pressed against a rigid surface over a step.
struct ElasticContact {
  int node = 0;
  Eigen::Vector3d normal;            ///< the surface's, pointing to the node
  Eigen::Vector3d surface_velocity;  ///< of the surface at the node
  double least_normal_velocity = 0;  ///< what normal . v must reach to end the step on it
  double start_depth = 0;            ///< how far inside the surface the node began the step
  double friction = 0;               ///< Coulomb's mu
  Eigen::Vector3d impulse{0, 0, 0};  ///< on the node (N s): in, the last step's; out, this one's
};

/// The contact nodes of the last step (in order) and their blocks of the inverse:
/// w[j * slots + i] is node j's velocity per impulse on node i, w_inverse[i] inverts w[i, i]. The
/// same nodes in contact (a steady grasp) reuse them.
struct ContactBlocks {
  std::vector<int> nodes;
  std::vector<Eigen::Matrix3d> w;
  std::vector<Eigen::Matrix3d> w_inverse;
};

/// The contact nodes last solved as stuck together (in order), and their system factored.
struct StuckSystem {
  std::vector<int> nodes;
  Eigen::LLT<Eigen::MatrixXd> factor;
};

/// Steps a soft body's nodes as a corotated solid of its material by linearly implicit (one
/// Newton step of backward) Euler: (M + h^2 K) v' = M v + h (f(x) + f_ext) + contact impulses.
/// K is the stiffness at rest turned by the body's overall rotation, so the matrix is factored
/// once per step size and every step costs one solve, whatever the material's stiffness: no
/// step is too long for it. At rest (v' = v = 0) the contacts carry exactly f(x) + f_ext, the
/// material's answer to the deformation, whatever the step.
///
/// The contacts are solved with that same matrix: each node's velocity answers an impulse on
/// any contact node through the inverse's 3x3 blocks, and a projected Gauss-Seidel finds the
/// impulses that leave every contact node on its surface and within its friction cone (sliding
/// against mu times its normal impulse, or stuck), warm started from the last step's.
class ImplicitElasticBody {
 public:
  /// `body`'s nodes as they are now are its rest shape; nodes of no mass stay where they are.
  ImplicitElasticBody(const btSoftBody& body, const SoftMaterial& material);

  /// One step of `h` from the nodes' positions (m_x) and velocities (m_v): their new velocities
  /// in m_v and positions in m_x (the start kept in m_q). `acceleration` per node is the
  /// external forces' (gravity); `contacts` get their impulses.
  void step(btSoftBody& body, double h, const std::vector<btVector3>& acceleration,
            std::vector<ElasticContact>& contacts);

 private:
  /// The velocity the nodes answer unit impulses on one node with (3 columns, rest frame).
  using Response = Eigen::Matrix<double, Eigen::Dynamic, 3>;

  void factor(double h);
  const Response& responseTo(int node);
  /// Follows the body's overall rotation (the polar rotation of its mass-weighted spread).
  void followBodyRotation(const Eigen::VectorXd& positions);
  /// The impulses that keep `contacts` on their surfaces, from the nodes' free velocities (all in
  /// the rest frame).
  void solveContacts(const Eigen::VectorXd& free_velocity, std::vector<ElasticContact>& contacts);

  CorotatedTets tets_;
  Eigen::VectorXd mass_;  ///< per coordinate; 0 for a node that stays put
  /// Each node's rest offset from the rest centre of mass times its mass (3 x nodes; empty when
  /// no node has mass).
  Eigen::Matrix3Xd weighted_rest_;
  Rotation body_rotation_;
  double factored_step_ = 0.0;
  NodeBlockCholesky system_;
  std::unordered_map<int, Response> responses_;  ///< by node, for the factored step
  ContactBlocks blocks_;                         ///< of the last step's contact nodes
  StuckSystem stuck_;
};

}  // namespace ambf_like::detail
