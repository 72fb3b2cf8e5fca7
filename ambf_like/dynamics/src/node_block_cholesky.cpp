#include "ambf_like/dynamics/node_block_cholesky.hpp"

#include <Eigen/LU>
#include <Eigen/OrderingMethods>
#include <Eigen/SparseCholesky>
#include <map>

namespace ambf_like::detail {

namespace {

/// `m`'s columns as four lanes each, the fourth 0.
std::array<Lanes, 3> columnsOf(const Eigen::Matrix3d& m) {
  std::array<Lanes, 3> columns;
  for (int c = 0; c < 3; ++c) columns[c] = Lanes{m(0, c), m(1, c), m(2, c), 0.0};
  return columns;
}

/// The block `m` times the vector `v` (lanes 0-2).
Lanes times(const std::array<Lanes, 3>& m, const Lanes& v) {
  return m[0] * v[0] + m[1] * v[1] + m[2] * v[2];
}

/// The sums of each of three lane sets' lanes, as one vector.
Lanes laneSums(const std::array<Lanes, 3>& sets) {
  Lanes out{};
  for (int c = 0; c < 3; ++c) out[c] = sets[c][0] + sets[c][1] + sets[c][2] + sets[c][3];
  return out;
}

/// Lane by lane sums of a block's columns times a vector: lane i of `sums[c]` summed over lanes
/// is column c's dot product with it.
void addColumnProducts(const std::array<Lanes, 3>& m, const Lanes& v, std::array<Lanes, 3>& sums) {
  for (int c = 0; c < 3; ++c) sums[c] += m[c] * v;
}

}  // namespace

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
        diagonal_inverse_[k] = columnsOf(block.inverse());
      } else {
        row_.push_back(row);
        below_.push_back(columnsOf(block));
      }
    }
    first_.push_back(static_cast<int>(row_.size()));
  }
  ordered_.resize(static_cast<std::size_t>(nodes));
  return true;
}

void NodeBlockCholesky::solveInPlace(Eigen::Ref<Eigen::VectorXd> x) {
  const int nodes = static_cast<int>(order_.size());
  std::vector<Lanes>& y = ordered_;
  for (int k = 0; k < nodes; ++k) {
    const auto at = x.segment<3>(3 * order_[k]);
    y[k] = Lanes{at[0], at[1], at[2], 0.0};
  }
  // L z = b, column by column; then L^T y = z, from the last node back.
  for (int k = 0; k < nodes; ++k) {
    const Lanes z = times(diagonal_inverse_[k], y[k]);
    y[k] = z;
    for (int b = first_[k]; b < first_[k + 1]; ++b) y[row_[b]] -= times(below_[b], z);
  }
  for (int k = nodes - 1; k >= 0; --k) {
    // rest = y_k - sum_b below_b^T y_row(b), then y_k = D_k^-T rest.
    std::array<Lanes, 3> sums{};
    for (int b = first_[k]; b < first_[k + 1]; ++b) addColumnProducts(below_[b], y[row_[b]], sums);
    const Lanes rest = y[k] - laneSums(sums);
    std::array<Lanes, 3> back{};
    addColumnProducts(diagonal_inverse_[k], rest, back);
    y[k] = laneSums(back);
  }
  for (int k = 0; k < nodes; ++k)
    x.segment<3>(3 * order_[k]) = Eigen::Vector3d(y[k][0], y[k][1], y[k][2]);
}

}  // namespace ambf_like::detail
