#include "ambf_like/dynamics/corotated_tets.hpp"

#include <BulletSoftBody/btSoftBody.h>

#include <Eigen/LU>
#include <algorithm>

#include "ambf_like/bullet_conversions.hpp"

namespace ambf_like::detail {

namespace {

/// The gradients of the four shape functions (columns; node 0 first) from the inverse rest
/// edge matrix.
Eigen::Matrix<double, 3, 4> shapeGradients(const Eigen::Matrix3d& rest_inverse) {
  Eigen::Matrix<double, 3, 4> g;
  g.rightCols<3>() = rest_inverse.transpose();
  g.col(0) = -(g.col(1) + g.col(2) + g.col(3));
  return g;
}

/// `m` in every lane.
Matrix9<Lanes> inEveryLane(const Eigen::Matrix3d& m) {
  Matrix9<Lanes> out;
  for (int e = 0; e < 9; ++e) out[e] = Lanes{} + m(e % 3, e / 3);
  return out;
}

}  // namespace

CorotatedTets::CorotatedTets(const btSoftBody& body, const SoftMaterial& material)
    : mu_(material.shearModulus()), lambda_(material.lameLambda()) {
  rest_.reserve(static_cast<std::size_t>(body.m_tetras.size()));
  for (int t = 0; t < body.m_tetras.size(); ++t) {
    const btSoftBody::Tetra& source = body.m_tetras[t];
    RestTetrahedron tet;
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
    rest_.push_back(tet);
  }
  for (std::size_t first = 0; first < rest_.size(); first += kLaneCount) {
    TetPack pack;
    pack.used = static_cast<int>(std::min<std::size_t>(kLaneCount, rest_.size() - first));
    for (int lane = 0; lane < kLaneCount; ++lane) {
      const RestTetrahedron& tet = rest_[first + (lane < pack.used ? lane : 0)];
      const Eigen::Matrix3d force_gradients = -tet.volume * tet.rest_inverse.transpose();
      pack.node[lane] = tet.node;
      pack.volume[lane] = lane < pack.used ? tet.volume : 0.0;
      for (int e = 0; e < 9; ++e) {
        pack.rest_inverse[e][lane] = tet.rest_inverse(e % 3, e / 3);
        pack.force_gradients[e][lane] = force_gradients(e % 3, e / 3);
      }
    }
    packs_.push_back(pack);
  }
}

void CorotatedTets::turnRotations(const Eigen::Quaterniond& turn) {
  const Matrix9<Lanes> by = inEveryLane(turn.toRotationMatrix());
  const double tw = turn.w(), tx = turn.x(), ty = turn.y(), tz = turn.z();
  for (auto& pack : packs_) {
    FollowedRotation<Lanes>& r = pack.rotation;
    const Lanes w = r.w, x = r.x, y = r.y, z = r.z;  // turn * q
    r.w = tw * w - (tx * x + ty * y + tz * z);
    r.x = tw * x + w * tx + (ty * z - tz * y);
    r.y = tw * y + w * ty + (tz * x - tx * z);
    r.z = tw * z + w * tz + (tx * y - ty * x);
    r.matrix = product(by, r.matrix);
  }
}

double CorotatedTets::addForces(const Eigen::VectorXd& positions, Eigen::VectorXd& forces) {
  const double* x = positions.data();
  Lanes energy{};
  for (auto& pack : packs_) {
    // The edge matrices [x1 - x0, x2 - x0, x3 - x0], lane by lane.
    Matrix9<Lanes> edges;
    for (int lane = 0; lane < kLaneCount; ++lane) {
      const std::array<int, 4>& node = pack.node[lane];
      const double* x0 = x + 3 * node[0];
      for (int k = 0; k < 3; ++k) {
        const double* xk = x + 3 * node[k + 1];
        for (int i = 0; i < 3; ++i) edges[3 * k + i][lane] = xk[i] - x0[i];
      }
    }
    const Matrix9<Lanes> u = followRotation(product(edges, pack.rest_inverse), pack.rotation);
    // The stress of the strain sym(U) - I (symmetric: six entries).
    const Lanes e00 = u[0] - 1.0, e11 = u[4] - 1.0, e22 = u[8] - 1.0;
    const Lanes e01 = 0.5 * (u[1] + u[3]), e02 = 0.5 * (u[2] + u[6]), e12 = 0.5 * (u[5] + u[7]);
    const Lanes pressure = lambda_ * (e00 + e11 + e22);
    const double twice_mu = 2.0 * mu_;
    const Matrix9<Lanes> stress{
        twice_mu * e00 + pressure, twice_mu * e01, twice_mu * e02, twice_mu * e01,
        twice_mu * e11 + pressure, twice_mu * e12, twice_mu * e02, twice_mu * e12,
        twice_mu * e22 + pressure};
    // Each node's force: minus the rest volume times the first Piola stress times its shape
    // function's gradient; node 0's gradient is minus the others' sum, so is its force.
    const Matrix9<Lanes> nodal =
        product(product(pack.rotation.matrix, stress), pack.force_gradients);
    // psi V = (mu eps : eps + lambda / 2 tr(eps)^2) V = (eps : stress) V / 2.
    const Lanes density = 0.5 * (e00 * stress[0] + e11 * stress[4] + e22 * stress[8]) +
                          (e01 * stress[1] + e02 * stress[2] + e12 * stress[5]);
    energy += density * pack.volume;
    for (int lane = 0; lane < pack.used; ++lane) {
      const std::array<int, 4>& node = pack.node[lane];
      double* f0 = forces.data() + 3 * node[0];
      for (int k = 0; k < 3; ++k) {
        double* fk = forces.data() + 3 * node[k + 1];
        for (int i = 0; i < 3; ++i) fk[i] += nodal[3 * k + i][lane];
      }
      for (int i = 0; i < 3; ++i) {
        f0[i] -= nodal[i][lane] + nodal[3 + i][lane] + nodal[6 + i][lane];
      }
    }
  }
  double total = 0.0;
  for (int lane = 0; lane < kLaneCount; ++lane) total += energy[lane];
  return total;
}

std::vector<Eigen::Triplet<double>> CorotatedTets::restStiffness() const {
  // K_ab = V (mu (g_a . g_b) I + mu g_b g_a^T + lambda g_a g_b^T), g the shape gradients.
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(rest_.size() * 144);
  for (const auto& tet : rest_) {
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
