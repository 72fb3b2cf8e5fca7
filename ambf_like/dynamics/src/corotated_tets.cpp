#include "ambf_like/dynamics/corotated_tets.hpp"

#include <BulletSoftBody/btSoftBody.h>

#include <Eigen/LU>
#include <cmath>
#include <optional>

#include "ambf_like/bullet_conversions.hpp"

namespace ambf_like::detail {

namespace {

/// The edge matrix [x1 - x0, x2 - x0, x3 - x0] of four nodes of `positions`.
Eigen::Matrix3d edges(const Eigen::VectorXd& positions, const std::array<int, 4>& node) {
  const Eigen::Vector3d x0 = positions.segment<3>(3 * node[0]);
  Eigen::Matrix3d d;
  for (int k = 0; k < 3; ++k) d.col(k) = positions.segment<3>(3 * node[k + 1]) - x0;
  return d;
}

/// The gradients of the four shape functions (columns; node 0 first) from the inverse rest
/// edge matrix.
Eigen::Matrix<double, 3, 4> shapeGradients(const Eigen::Matrix3d& rest_inverse) {
  Eigen::Matrix<double, 3, 4> g;
  g.rightCols<3>() = rest_inverse.transpose();
  g.col(0) = -(g.col(1) + g.col(2) + g.col(3));
  return g;
}

/// (tr S I - S)^-1 torque, S = sym(unrotated), by its adjugate; none unless that matrix is
/// positive definite (its leading minors positive).
std::optional<Eigen::Vector3d> newtonTurn(const Eigen::Matrix3d& unrotated,
                                          const Eigen::Vector3d& torque) {
  const Eigen::Matrix3d s = 0.5 * (unrotated + unrotated.transpose());
  const Eigen::Matrix3d m = s.trace() * Eigen::Matrix3d::Identity() - s;
  const double c00 = m(1, 1) * m(2, 2) - m(1, 2) * m(1, 2);
  const double c01 = m(0, 2) * m(1, 2) - m(0, 1) * m(2, 2);
  const double c02 = m(0, 1) * m(1, 2) - m(0, 2) * m(1, 1);
  const double c11 = m(0, 0) * m(2, 2) - m(0, 2) * m(0, 2);
  const double c12 = m(0, 1) * m(0, 2) - m(0, 0) * m(1, 2);
  const double c22 = m(0, 0) * m(1, 1) - m(0, 1) * m(0, 1);
  const double det = m(0, 0) * c00 + m(0, 1) * c01 + m(0, 2) * c02;
  if (!(m(0, 0) > 0.0 && c22 > 0.0 && det > 0.0)) return std::nullopt;
  Eigen::Matrix3d adjugate;
  adjugate << c00, c01, c02, c01, c11, c12, c02, c12, c22;
  return adjugate * torque / det;
}

}  // namespace

Eigen::Matrix3d followRotation(const Eigen::Matrix3d& f, Rotation& rotation) {
  // With U = R^T F, R is F's polar rotation when U is symmetric: when the torque
  // sum_i r_i x f_i = R t, t = (U21 - U12, U02 - U20, U10 - U01), vanishes. Turning R by a small
  // d in its own frame changes t by -(tr S I - S) d, S = sym(U), so each iteration turns R by
  // Newton's d = (tr S I - S)^-1 t (the quaternion (1, d / 2) normalised, multiplied from the
  // right), which converges quadratically while S is positive definite. Mueller et al.'s
  // (2016) turn t / tr U is the fallback for an element too crushed for that: it is safe at
  // any stretch but takes only part of the turn (a third of what is left stays, at S = I).
  // The test: |t| / |tr U| below 1e-4, about two thirds of the angle left; that moves a force
  // by about 1e-4 of the stress (to first order in the turn times the strain).
  constexpr int kMostIterations = 4;
  constexpr double kConverged = 1e-4;
  Eigen::Matrix3d unrotated = rotation.matrix.transpose() * f;
  for (int i = 0; i < kMostIterations; ++i) {
    const Eigen::Vector3d torque(unrotated(2, 1) - unrotated(1, 2),
                                 unrotated(0, 2) - unrotated(2, 0),
                                 unrotated(1, 0) - unrotated(0, 1));
    // Compared before dividing (most calls end here).
    const double scale = std::abs(unrotated.trace()) + 1e-9;
    if (!(torque.squaredNorm() > kConverged * kConverged * scale * scale)) break;
    const Eigen::Vector3d half_turn = 0.5 * newtonTurn(unrotated, torque).value_or(torque / scale);
    rotation.quaternion *= Eigen::Quaterniond(1.0, half_turn.x(), half_turn.y(), half_turn.z());
    rotation.quaternion.normalize();
    rotation.matrix = rotation.quaternion.toRotationMatrix();
    unrotated = rotation.matrix.transpose() * f;
  }
  return unrotated;
}

CorotatedTets::CorotatedTets(const btSoftBody& body, const SoftMaterial& material)
    : mu_(material.shearModulus()), lambda_(material.lameLambda()) {
  tets_.reserve(static_cast<std::size_t>(body.m_tetras.size()));
  for (int t = 0; t < body.m_tetras.size(); ++t) {
    const btSoftBody::Tetra& source = body.m_tetras[t];
    Tetrahedron tet;
    for (int k = 0; k < 4; ++k) tet.node[k] = static_cast<int>(source.m_n[k] - &body.m_nodes[0]);
    Eigen::Matrix3d rest;
    for (int k = 0; k < 3; ++k) {
      rest.col(k) = toEigen(body.m_nodes[tet.node[k + 1]].m_x - body.m_nodes[tet.node[0]].m_x);
    }
    if (rest.determinant() < 0.0) {  // every tetrahedron positively oriented
      std::swap(tet.node[1], tet.node[2]);
      rest.col(0).swap(rest.col(1));
    }
    tet.volume = rest.determinant() / 6.0;
    if (!(tet.volume > 0.0)) continue;  // a flat tetrahedron carries no elasticity
    tet.rest_inverse = rest.inverse();
    tet.force_gradients = -tet.volume * tet.rest_inverse.transpose();
    tets_.push_back(tet);
  }
}

void CorotatedTets::turnRotations(const Eigen::Quaterniond& turn) {
  const Eigen::Matrix3d turn_matrix = turn.toRotationMatrix();
  for (auto& tet : tets_) {
    tet.rotation.quaternion = turn * tet.rotation.quaternion;
    tet.rotation.matrix = turn_matrix * tet.rotation.matrix;
  }
}

void CorotatedTets::addForces(const Eigen::VectorXd& positions, Eigen::VectorXd& forces) {
  const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  for (auto& tet : tets_) {
    const Eigen::Matrix3d f = edges(positions, tet.node) * tet.rest_inverse;
    const Eigen::Matrix3d unrotated = followRotation(f, tet.rotation);
    const Eigen::Matrix3d& r = tet.rotation.matrix;
    const Eigen::Matrix3d strain = 0.5 * (unrotated + unrotated.transpose()) - identity;
    const Eigen::Matrix3d stress = 2.0 * mu_ * strain + lambda_ * strain.trace() * identity;
    // Each node's force: minus the rest volume times the first Piola stress times its shape
    // function's gradient; node 0's gradient is minus the others' sum, so is its force.
    const Eigen::Matrix3d nodal = (r * stress) * tet.force_gradients;
    for (int k = 0; k < 3; ++k) forces.segment<3>(3 * tet.node[k + 1]) += nodal.col(k);
    forces.segment<3>(3 * tet.node[0]) -= nodal.rowwise().sum();
  }
}

std::vector<Eigen::Triplet<double>> CorotatedTets::restStiffness() const {
  // K_ab = V (mu (g_a . g_b) I + mu g_b g_a^T + lambda g_a g_b^T), g the shape gradients.
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(tets_.size() * 144);
  for (const auto& tet : tets_) {
    const Eigen::Matrix<double, 3, 4> g = shapeGradients(tet.rest_inverse);
    for (int a = 0; a < 4; ++a) {
      for (int b = 0; b < 4; ++b) {
        const Eigen::Matrix3d block =
            tet.volume *
            (mu_ * g.col(a).dot(g.col(b)) * Eigen::Matrix3d::Identity() +
             mu_ * g.col(b) * g.col(a).transpose() + lambda_ * g.col(a) * g.col(b).transpose());
        for (int i = 0; i < 3; ++i) {
          for (int j = 0; j < 3; ++j) {
            triplets.emplace_back(3 * tet.node[a] + i, 3 * tet.node[b] + j, block(i, j));
          }
        }
      }
    }
  }
  return triplets;
}

}  // namespace ambf_like::detail
