// A sparse Cholesky factor kept in 3x3 node blocks solves as a dense factorisation does.

#include "ambf_like/dynamics/node_block_cholesky.hpp"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/SparseCore>
#include <random>

namespace {

using ambf_like::detail::NodeBlockCholesky;

/// A mass-plus-stiffness-like matrix of `nodes` nodes on a ring, each coupled by a random 3x3
/// block to its two neighbours on each side (a ring's graph leaves fill however it is ordered).
Eigen::SparseMatrix<double> ringSystem(int nodes, std::mt19937& random) {
  std::uniform_real_distribution<double> entry(-1.0, 1.0);
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(3 * nodes, 3 * nodes);
  for (int a = 0; a < nodes; ++a) {
    for (const int step : {1, 2}) {
      const int b = (a + step) % nodes;
      Eigen::Matrix3d coupling;
      for (double& c : coupling.reshaped()) c = entry(random);
      dense.block<3, 3>(3 * a, 3 * b) += coupling;
      dense.block<3, 3>(3 * b, 3 * a) += coupling.transpose();
    }
  }
  // Diagonally dominant, so positive definite.
  dense += 13.0 * Eigen::MatrixXd::Identity(3 * nodes, 3 * nodes);
  return dense.sparseView();
}

TEST(NodeBlockCholesky, SolvesAsADenseCholeskyDoes) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> entry(-1.0, 1.0);
  const Eigen::SparseMatrix<double> system = ringSystem(40, random);
  NodeBlockCholesky factor;
  ASSERT_TRUE(factor.compute(system));
  const Eigen::LLT<Eigen::MatrixXd> dense{Eigen::MatrixXd(system)};
  for (int trial = 0; trial < 3; ++trial) {
    Eigen::VectorXd b(system.rows());
    for (double& v : b) v = entry(random);
    Eigen::VectorXd x = b;
    factor.solveInPlace(x);
    EXPECT_LT((x - dense.solve(b)).norm(), 1e-12 * b.norm());
    EXPECT_LT((system * x - b).norm(), 1e-12 * b.norm());
  }
}

TEST(NodeBlockCholesky, RefusesAMatrixThatIsNotPositiveDefinite) {
  std::mt19937 random(5);
  Eigen::SparseMatrix<double> system = ringSystem(10, random);
  system.coeffRef(4, 4) = -50.0;
  NodeBlockCholesky factor;
  EXPECT_FALSE(factor.compute(system));
}

}  // namespace
