#pragma once
// A soft body's tetrahedra as a corotated linear-elastic solid: its forces and its stiffness.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/SparseCore>
#include <array>
#include <vector>

#include "ambf_like/soft_body_spec.hpp"

class btSoftBody;

namespace ambf_like::detail {

/// A rotation followed from step to step: as a unit quaternion, and as the matrix it makes.
struct Rotation {
  Eigen::Quaterniond quaternion = Eigen::Quaterniond::Identity();
  Eigen::Matrix3d matrix = Eigen::Matrix3d::Identity();
};

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
/// and blew 3 of 20 randomised peg scenes apart (seeds 6, 11 and 20 of the batch test).
class CorotatedTets {
 public:
  /// The tetrahedra of `body` (rest shape: the nodes where they are now).
  CorotatedTets(const btSoftBody& body, const SoftMaterial& material);

  /// Turns every tetrahedron's followed rotation by `turn` (the body's own turn since the last
  /// forces): a start for the iteration that leaves it only the tetrahedron's own turn to follow.
  void turnRotations(const Eigen::Quaterniond& turn);
  /// Adds each node's elastic force (N) at `positions` (3 per node) to `forces`.
  void addForces(const Eigen::VectorXd& positions, Eigen::VectorXd& forces);
  /// The stiffness matrix at rest (3 rows per node), as triplets.
  std::vector<Eigen::Triplet<double>> restStiffness() const;

 private:
  /// One tetrahedron: its nodes, inverse rest edge matrix, rest volume and current rotation.
  struct Tetrahedron {
    std::array<int, 4> node;
    Eigen::Matrix3d rest_inverse;
    Eigen::Matrix3d force_gradients;  ///< minus the volume times nodes 1-3's gradients
    double volume = 0.0;
    Rotation rotation;
  };

  double mu_;
  double lambda_;
  std::vector<Tetrahedron> tets_;
};

/// Updates `rotation` towards the rotation of `f`'s polar decomposition (at most 4 iterations,
/// none once within 1e-4 rad); returns R^T f for the rotation it ends with.
Eigen::Matrix3d followRotation(const Eigen::Matrix3d& f, Rotation& rotation);

}  // namespace ambf_like::detail
