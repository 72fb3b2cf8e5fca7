#pragma once
// A soft body's tetrahedra as a corotated linear-elastic solid: its forces and its stiffness.

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <array>
#include <vector>

#include "ambf_like/dynamics/lane_matrix.hpp"
#include "ambf_like/dynamics/polar_rotation.hpp"
#include "ambf_like/soft_body_spec.hpp"

class btSoftBody;

namespace ambf_like::detail {

/// The corotated linear-elastic solid (Mueller et al. 2002; energy per rest volume
/// psi = mu |eps|^2 + lambda/2 tr(eps)^2 with eps = sym(R^T F) - I, R the rotation of F): small
/// strains answer as linear elasticity with the material's E and nu, and a rigid rotation of
/// any size costs nothing. A uniaxial stretch s with free sides answers with the nominal stress
/// E (s - 1) exactly, at any strain.
///
/// Each tetrahedron's rotation is followed from step to step (followRotation: Newton's turn on
/// the torque of Mueller, Bender, Chentanez and Macklin's (2016) iteration), started from the last
/// one turned by the body's own turn (turnRotations), to within 1e-4 rad (at most 4 iterations a
/// step). One of that paper's iterations per step let the rotations lag a ring that turned fast
/// and blew 3 of 20 randomised peg-transfer scenes apart (seeds 6, 11 and 20 of the batch test).
///
/// The tetrahedra are stored and worked on four at a time, lane by lane (TetPack): the same
/// arithmetic per tetrahedron as one at a time, rotations followed too, in a quarter of the
/// instructions.
class CorotatedTets {
 public:
  /// The tetrahedra of `body` (rest shape: the nodes where they are now).
  CorotatedTets(const btSoftBody& body, const SoftMaterial& material);

  /// Turns every tetrahedron's followed rotation by `turn` (the body's own turn since the last
  /// forces): a start for the iteration that leaves it only the tetrahedron's own turn to follow.
  void turnRotations(const Eigen::Quaterniond& turn);
  /// Adds each node's elastic force (N) at `positions` (3 per node) to `forces`; returns the
  /// elastic energy stored at `positions` (J), of which the forces are minus the gradient.
  double addForces(const Eigen::VectorXd& positions, Eigen::VectorXd& forces);
  /// The stiffness matrix at rest (3 rows per node), as triplets.
  std::vector<Eigen::Triplet<double>> restStiffness() const;

 private:
  /// One tetrahedron's rest shape: its nodes (positively oriented), inverse rest edge matrix
  /// and rest volume.
  struct RestTetrahedron {
    std::array<int, 4> node;
    Eigen::Matrix3d rest_inverse;
    double volume = 0.0;
  };
  /// Up to four tetrahedra stored lane by lane, with what their forces need each step: the
  /// constants of the rest shape and each one's followed rotation. A pack's unused lanes repeat
  /// its first tetrahedron, and their forces are not added.
  struct TetPack {
    int used = 0;
    std::array<std::array<int, 4>, kLaneCount> node;
    Lanes volume;  ///< at rest; 0 in the unused lanes
    Matrix9<Lanes> rest_inverse;
    Matrix9<Lanes> force_gradients;  ///< minus the volume times nodes 1-3's gradients
    FollowedRotation<Lanes> rotation;
  };

  double mu_;
  double lambda_;
  std::vector<RestTetrahedron> rest_;
  std::vector<TetPack> packs_;
};

}  // namespace ambf_like::detail
