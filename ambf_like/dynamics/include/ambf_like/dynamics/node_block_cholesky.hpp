#pragma once
// A sparse Cholesky factor kept as 3x3 blocks, one per pair of nodes, for fast repeated solves.

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <array>
#include <vector>

#include "ambf_like/dynamics/lane_matrix.hpp"

namespace ambf_like::detail {

/// Factors a symmetric positive definite matrix with 3 rows per node (a mesh's stiffness and
/// mass) as L L^T in a fill-reducing order of the nodes (AMD on the nodes' graph), and keeps L as
/// dense 3x3 blocks. A solve then walks the blocks instead of single entries: the same work as a
/// scalar sparse solve in about a third of the time (a 144-node ring: 2,138 blocks, ~10 us
/// against ~30 us for Eigen's SimplicialLDLT on the same order). Each block is kept as three
/// four-lane columns (the fourth lane 0) and each node's 3-vector as four lanes, so a block
/// times a vector is three multiply-adds of four lanes.
class NodeBlockCholesky {
 public:
  /// Factors `matrix` (3 rows per node; the lower triangle is read); false if it is not positive
  /// definite.
  bool compute(const Eigen::SparseMatrix<double>& matrix);
  /// Replaces `x` by the matrix's inverse times `x`.
  void solveInPlace(Eigen::Ref<Eigen::VectorXd> x);

 private:
  std::vector<int> order_;  ///< order_[k]: the node eliminated k-th
  /// The blocks below the diagonal of L, by column: column k's are first_[k] .. first_[k + 1] - 1,
  /// in row_ (the row's position in the order) and below_.
  std::vector<int> first_;
  std::vector<int> row_;
  /// A 3x3 block as its three columns of four lanes (x, y, z, 0).
  using Block = std::array<Lanes, 3>;
  std::vector<Block> below_;
  std::vector<Block> diagonal_inverse_;  ///< of L's diagonal blocks (lower triangular)
  std::vector<Lanes> ordered_;           ///< a solve's scratch, one node a lane set, in order
};

}  // namespace ambf_like::detail
