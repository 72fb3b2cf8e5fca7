#include "neo_hookean_tets.hpp"

#include <BulletSoftBody/btSoftBody.h>

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

namespace ambf_like::detail {

namespace {

Eigen::Vector3d position(const btSoftBody& body, int node) {
  const btVector3& x = body.m_nodes[node].m_x;
  return {x.x(), x.y(), x.z()};
}

/// The edge matrix [x1 - x0, x2 - x0, x3 - x0] of four nodes.
Eigen::Matrix3d edges(const btSoftBody& body, const std::array<int, 4>& node) {
  const Eigen::Vector3d x0 = position(body, node[0]);
  Eigen::Matrix3d d;
  for (int k = 0; k < 3; ++k) d.col(k) = position(body, node[k + 1]) - x0;
  return d;
}

/// d det(F) / dF: the cofactor matrix, columns f2 x f3, f3 x f1, f1 x f2.
Eigen::Matrix3d cofactor(const Eigen::Matrix3d& f) {
  Eigen::Matrix3d c;
  c.col(0) = f.col(1).cross(f.col(2));
  c.col(1) = f.col(2).cross(f.col(0));
  c.col(2) = f.col(0).cross(f.col(1));
  return c;
}

/// A constraint's value and its gradient with respect to F.
struct ConstraintValue {
  double c;
  Eigen::Matrix3d gradient;
};

ConstraintValue evaluate(const Eigen::Matrix3d& f, int which, double gamma) {
  if (which == 0) {
    const double norm = f.norm();
    return {norm, f / norm};
  }
  return {f.determinant() - gamma, cofactor(f)};
}

/// The four nodes' gradients (columns 1-3: nodes 1-3; node 0 is minus their sum).
Eigen::Matrix3d nodeGradients(const Eigen::Matrix3d& gradient_f, const Eigen::Matrix3d& rest_inv) {
  return gradient_f * rest_inv.transpose();
}

// A Gauss-Seidel pass with warm-started multipliers behaves like an explicit step: stable while
// the substep is below about 1 / omega (omega: the highest natural frequency). Gershgorin's bound
// over-estimates omega, which leaves a margin.
constexpr double kStabilityFactor = 1.0;

}  // namespace

NeoHookeanTets::NeoHookeanTets(const btSoftBody& body, const SoftMaterial& material)
    : mu_(material.shearModulus()), lambda_(material.lameLambda() + material.shearModulus()) {
  gamma_ = 1.0 + mu_ / lambda_;
  const double stiffness[2] = {mu_, lambda_};
  // Gershgorin row sums of M^-1 K at rest, per node.
  std::vector<double> row_sum(static_cast<std::size_t>(body.m_nodes.size()), 0.0);
  tets_.reserve(static_cast<std::size_t>(body.m_tetras.size()));
  for (int t = 0; t < body.m_tetras.size(); ++t) {
    const btSoftBody::Tetra& source = body.m_tetras[t];
    Tetrahedron tet;
    for (int k = 0; k < 4; ++k) tet.node[k] = static_cast<int>(source.m_n[k] - &body.m_nodes[0]);
    const Eigen::Matrix3d rest = edges(body, tet.node);
    if (rest.determinant() < 0.0) {
      std::swap(tet.node[1], tet.node[2]);  // every tetrahedron positively oriented
    }
    const Eigen::Matrix3d oriented = edges(body, tet.node);
    tet.volume = oriented.determinant() / 6.0;
    if (!(tet.volume > 0.0)) continue;  // a flat tetrahedron carries no elasticity
    tet.rest_inverse = oriented.inverse();
    const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
    for (int which = 0; which < 2; ++which) {
      const ConstraintValue value = evaluate(identity, which, gamma_);
      // At rest the two constraints' forces cancel: start from them, not from a collapse.
      tet.force[which] = -value.c * stiffness[which] * tet.volume;
      const Eigen::Matrix3d g = nodeGradients(value.gradient, tet.rest_inverse);
      std::array<double, 4> size{(g.col(0) + g.col(1) + g.col(2)).norm(), 0, 0, 0};
      for (int k = 0; k < 3; ++k) size[k + 1] = g.col(k).norm();
      double total = 0.0;
      for (double s : size) total += s;
      for (int k = 0; k < 4; ++k) {
        row_sum[static_cast<std::size_t>(tet.node[k])] +=
            stiffness[which] * tet.volume * size[k] * total;
      }
    }
    tets_.push_back(tet);
  }
  double omega_squared = 0.0;
  for (int i = 0; i < body.m_nodes.size(); ++i) {
    omega_squared =
        std::max(omega_squared, body.m_nodes[i].m_im * row_sum[static_cast<std::size_t>(i)]);
  }
  stable_substep_ = omega_squared > 0.0 ? kStabilityFactor / std::sqrt(omega_squared) : 1.0;
  // Damps the highest mode at about half of critical; the modes a 1 kHz loop sees hardly at all.
  damping_time_ = omega_squared > 0.0 ? 1.0 / std::sqrt(omega_squared) : 0.0;
}

void NeoHookeanTets::warmStart(btSoftBody& body, double h) {
  // Every constraint's last force is applied from one configuration, all at once: applied one
  // after another, the large opposite forces a Neo-Hookean solid carries at rest (its deviatoric
  // and hydrostatic parts) would cancel only to first order, and the remainder spins the body up.
  shift_.assign(static_cast<std::size_t>(body.m_nodes.size()), Eigen::Vector3d::Zero());
  for (auto& tet : tets_) {
    const Eigen::Matrix3d f = edges(body, tet.node) * tet.rest_inverse;
    Eigen::Matrix3d push = Eigen::Matrix3d::Zero();
    for (int which = 0; which < 2; ++which) {
      tet.multiplier[which] = tet.force[which] * h * h;
      push += evaluate(f, which, gamma_).gradient * tet.multiplier[which];
    }
    const Eigen::Matrix3d g = nodeGradients(push, tet.rest_inverse);
    shift_[static_cast<std::size_t>(tet.node[0])] -= g.col(0) + g.col(1) + g.col(2);
    for (int k = 0; k < 3; ++k) shift_[static_cast<std::size_t>(tet.node[k + 1])] += g.col(k);
  }
  for (int i = 0; i < body.m_nodes.size(); ++i) {
    btSoftBody::Node& n = body.m_nodes[i];
    const Eigen::Vector3d step = n.m_im * shift_[static_cast<std::size_t>(i)];
    n.m_x += btVector3(step.x(), step.y(), step.z());
  }
}

void NeoHookeanTets::iterate(btSoftBody& body, double h) {
  for (auto& tet : tets_) {
    for (int which = 0; which < 2; ++which) solve(body, tet, which, h);
  }
}

void NeoHookeanTets::finishSubstep(double h) {
  for (auto& tet : tets_) {
    for (int which = 0; which < 2; ++which) tet.force[which] = tet.multiplier[which] / (h * h);
  }
}

void NeoHookeanTets::solve(btSoftBody& body, Tetrahedron& tet, int which, double h) const {
  const Eigen::Matrix3d f = edges(body, tet.node) * tet.rest_inverse;
  const ConstraintValue value = evaluate(f, which, gamma_);
  const Eigen::Matrix3d g = nodeGradients(value.gradient, tet.rest_inverse);
  const Eigen::Vector3d g0 = -(g.col(0) + g.col(1) + g.col(2));
  double weighted = body.m_nodes[tet.node[0]].m_im * g0.squaredNorm();
  for (int k = 0; k < 3; ++k) {
    weighted += body.m_nodes[tet.node[k + 1]].m_im * g.col(k).squaredNorm();
  }
  const double stiffness = which == 0 ? mu_ : lambda_;
  const double compliance = 1.0 / (stiffness * tet.volume * h * h);
  // Stiffness-proportional (Rayleigh) damping of the strain rate over this substep.
  const double damping = damping_time_ / h;
  double rate = (body.m_nodes[tet.node[0]].m_x - body.m_nodes[tet.node[0]].m_q)
                    .dot(btVector3(g0.x(), g0.y(), g0.z()));
  for (int k = 0; k < 3; ++k) {
    const btSoftBody::Node& n = body.m_nodes[tet.node[k + 1]];
    rate += (n.m_x - n.m_q).dot(btVector3(g(0, k), g(1, k), g(2, k)));
  }
  const double delta = (-value.c - compliance * tet.multiplier[which] - damping * rate) /
                       ((1.0 + damping) * weighted + compliance);
  tet.multiplier[which] += delta;
  auto move = [&](int node, const Eigen::Vector3d& gradient) {
    btSoftBody::Node& n = body.m_nodes[node];
    const Eigen::Vector3d step = n.m_im * delta * gradient;
    n.m_x += btVector3(step.x(), step.y(), step.z());
  };
  move(tet.node[0], g0);
  for (int k = 0; k < 3; ++k) move(tet.node[k + 1], g.col(k));
}

}  // namespace ambf_like::detail
