// A corotated solid's elastic forces, worked four tetrahedra at a time, are the textbook
// corotated forces of every tetrahedron: P = R (2 mu eps + lambda tr(eps) I), eps = sym(R^T F) - I,
// R the polar rotation of F, each node's force -V P grad N.

#include <BulletSoftBody/btSoftBody.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <cmath>
#include <random>

#include "ambf_like/dynamics/corotated_tets.hpp"

namespace {

using ambf_like::SoftMaterial;
using ambf_like::detail::CorotatedTets;

/// The polar rotation of `f` (a proper rotation).
Eigen::Matrix3d polarRotation(const Eigen::Matrix3d& f) {
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(f, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d u = svd.matrixU();
  if ((u * svd.matrixV().transpose()).determinant() < 0.0) u.col(2) *= -1.0;
  return u * svd.matrixV().transpose();
}

/// The corotated forces of `tets` (each positively oriented at `rest`) at `now`, one by one.
Eigen::VectorXd textbookForces(const std::vector<std::array<int, 4>>& tets,
                               const Eigen::Matrix3Xd& rest, const Eigen::Matrix3Xd& now, double mu,
                               double lambda) {
  Eigen::VectorXd forces = Eigen::VectorXd::Zero(3 * rest.cols());
  for (const auto& t : tets) {
    Eigen::Matrix3d dm, ds;
    for (int k = 0; k < 3; ++k) {
      dm.col(k) = rest.col(t[k + 1]) - rest.col(t[0]);
      ds.col(k) = now.col(t[k + 1]) - now.col(t[0]);
    }
    const double volume = std::abs(dm.determinant()) / 6.0;
    const Eigen::Matrix3d f = ds * dm.inverse();
    const Eigen::Matrix3d r = polarRotation(f);
    const Eigen::Matrix3d u = r.transpose() * f;
    const Eigen::Matrix3d eps = 0.5 * (u + u.transpose()) - Eigen::Matrix3d::Identity();
    const Eigen::Matrix3d p =
        r * (2.0 * mu * eps + lambda * eps.trace() * Eigen::Matrix3d::Identity());
    const Eigen::Matrix3d nodal = -volume * p * dm.inverse().transpose();  // nodes 1-3
    for (int k = 0; k < 3; ++k) {
      forces.segment<3>(3 * t[k + 1]) += nodal.col(k);
      forces.segment<3>(3 * t[0]) -= nodal.col(k);
    }
  }
  return forces;
}

TEST(CorotatedForces, FourAtATimeTheyAreEachTetrahedronsTextbookForces) {
  // Two cubes of 2 mm side by side cut into 6 tetrahedra each (12; and 7, the first cube and one
  // of the second: packs of four with lanes to spare), turned 1 rad and strained unevenly.
  for (const int count : {12, 7}) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> jitter(-1e-4, 1e-4);
    Eigen::Matrix3Xd rest(3, 12);
    for (int n = 0; n < 12; ++n) {
      rest.col(n) = 2e-3 * Eigen::Vector3d(n % 3, (n / 3) % 2, n / 6);
    }
    btSoftBodyWorldInfo info;
    std::vector<btVector3> x;
    for (int n = 0; n < 12; ++n) x.emplace_back(rest(0, n), rest(1, n), rest(2, n));
    std::vector<btScalar> masses(12, 1e-4);
    btSoftBody body(&info, 12, x.data(), masses.data());
    // Cube c's corners: node (i + c, j, k) is i + c + 3 j + 6 k.
    std::vector<std::array<int, 4>> tets;
    const int around[6][2] = {{1, 3}, {1, 5}, {2, 3}, {2, 6}, {4, 5}, {4, 6}};
    for (int c = 0; c < 2; ++c) {
      auto corner = [&](int bits) {
        return c + (bits & 1) + 3 * ((bits >> 1) & 1) + 6 * (bits >> 2);
      };
      for (const auto& a : around)
        tets.push_back({corner(0), corner(a[0]), corner(a[1]), corner(7)});
    }
    tets.resize(static_cast<std::size_t>(count));
    for (auto& t : tets) {
      Eigen::Matrix3d dm;
      for (int k = 0; k < 3; ++k) dm.col(k) = rest.col(t[k + 1]) - rest.col(t[0]);
      if (dm.determinant() < 0.0) std::swap(t[1], t[2]);
      body.appendTetra(t[0], t[1], t[2], t[3]);
    }
    const SoftMaterial material{.youngs_modulus = 1e6, .poissons_ratio = 0.45, .density = 1100};
    CorotatedTets solid(body, material);

    const Eigen::Matrix3d turn =
        Eigen::AngleAxisd(1.0, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
    Eigen::Matrix3d stretch;
    stretch << 1.08, 0.03, 0.0, 0.0, 0.95, 0.02, 0.01, 0.0, 1.02;
    Eigen::Matrix3Xd now = turn * stretch * rest;
    for (int n = 0; n < 12; ++n) now.col(n) += Eigen::Vector3d(jitter(random), jitter(random), 0);
    const Eigen::VectorXd positions = Eigen::Map<const Eigen::VectorXd>(now.data(), now.size());
    Eigen::VectorXd forces;
    for (int call = 0; call < 4; ++call) {  // the rotations followed from rest over some calls
      forces = Eigen::VectorXd::Zero(positions.size());
      solid.addForces(positions, forces);
    }
    const Eigen::VectorXd expected =
        textbookForces(tets, rest, now, material.shearModulus(), material.lameLambda());
    // Within the rotations' tolerance (1e-4 rad) of the largest force.
    EXPECT_GT(expected.norm(), 0.1);  // newtons: the strain really loads it
    EXPECT_LT((forces - expected).cwiseAbs().maxCoeff(), 1e-3 * expected.cwiseAbs().maxCoeff())
        << count << " tetrahedra";
  }
}

}  // namespace
