#include "ambf_like/dynamics/node_block_cholesky.hpp"

#include <Eigen/LU>
#include <Eigen/OrderingMethods>
#include <Eigen/SparseCholesky>
#include <map>

namespace ambf_like::detail {

bool NodeBlockCholesky::compute(const Eigen::SparseMatrix<double>& matrix) {
  const auto nodes = static_cast<int>(matrix.rows() / 3);
  // The nodes' graph, and its fill-reducing order.
  std::vector<Eigen::Triplet<double>> links;
  for (int c = 0; c < matrix.outerSize(); ++c) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(matrix, c); it; ++it) {
      links.emplace_back(static_cast<int>(it.row() / 3), c / 3, 1.0);
    }
  }
  Eigen::SparseMatrix<double> graph(nodes, nodes);
  graph.setFromTriplets(links.begin(), links.end());
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> amd;
  Eigen::AMDOrdering<int>()(graph, amd);
  order_.assign(amd.indices().data(), amd.indices().data() + nodes);
  std::vector<int> position(nodes);
  for (int k = 0; k < nodes; ++k) position[order_[k]] = k;
  auto at = [&](Eigen::Index i) { return 3 * position[i / 3] + static_cast<int>(i % 3); };

  // Eigen factors the reordered matrix entry by entry; its L is then cut into blocks.
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(matrix.nonZeros()));
  for (int c = 0; c < matrix.outerSize(); ++c) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(matrix, c); it; ++it) {
      entries.emplace_back(at(it.row()), at(c), it.value());
    }
  }
  Eigen::SparseMatrix<double> reordered(matrix.rows(), matrix.cols());
  reordered.setFromTriplets(entries.begin(), entries.end());
  const Eigen::SimplicialLLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>>
      factor(reordered);
  if (factor.info() != Eigen::Success) return false;
  const Eigen::SparseMatrix<double> lower = factor.matrixL();
  std::vector<std::map<int, Eigen::Matrix3d>> columns(nodes);
  for (int c = 0; c < lower.outerSize(); ++c) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(lower, c); it; ++it) {
      auto& block = columns[c / 3]
                        .try_emplace(static_cast<int>(it.row() / 3), Eigen::Matrix3d::Zero())
                        .first->second;
      block(it.row() % 3, c % 3) = it.value();
    }
  }
  first_.assign(1, 0);
  row_.clear();
  below_.clear();
  diagonal_inverse_.resize(nodes);
  for (int k = 0; k < nodes; ++k) {
    for (const auto& [row, block] : columns[k]) {
      if (row == k) {
        diagonal_inverse_[k] = block.inverse();
      } else {
        row_.push_back(row);
        below_.push_back(block);
      }
    }
    first_.push_back(static_cast<int>(row_.size()));
  }
  ordered_.resize(matrix.rows());
  return true;
}

void NodeBlockCholesky::solveInPlace(Eigen::Ref<Eigen::VectorXd> x) {
  const int nodes = static_cast<int>(order_.size());
  Eigen::Map<Eigen::Matrix3Xd> y(ordered_.data(), 3, nodes);
  for (int k = 0; k < nodes; ++k) y.col(k) = x.segment<3>(3 * order_[k]);
  // L z = b, column by column; then L^T y = z, from the last node back.
  for (int k = 0; k < nodes; ++k) {
    const Eigen::Vector3d z = diagonal_inverse_[k] * y.col(k);
    y.col(k) = z;
    for (int b = first_[k]; b < first_[k + 1]; ++b) y.col(row_[b]).noalias() -= below_[b] * z;
  }
  for (int k = nodes - 1; k >= 0; --k) {
    Eigen::Vector3d rest = y.col(k);
    for (int b = first_[k]; b < first_[k + 1]; ++b) {
      rest.noalias() -= below_[b].transpose() * y.col(row_[b]);
    }
    y.col(k) = diagonal_inverse_[k].transpose() * rest;
  }
  for (int k = 0; k < nodes; ++k) x.segment<3>(3 * order_[k]) = y.col(k);
}

}  // namespace ambf_like::detail
