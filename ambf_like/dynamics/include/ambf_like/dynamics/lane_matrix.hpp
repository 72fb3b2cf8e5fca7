#pragma once
// 3x3 matrices of numbers or of four-lane vectors: the same arithmetic for one tetrahedron or
// for four side by side.

#include <array>
#include <cmath>

namespace ambf_like::detail {

/// Four numbers side by side, one per tetrahedron of a pack: one instruction works on all.
using Lanes = double __attribute__((vector_size(32)));
/// How many numbers Lanes holds.
inline constexpr int kLaneCount = 4;
/// Which lanes a comparison of Lanes held in (all bits set) or not (zero).
using LaneMask = decltype(Lanes{} < Lanes{});

/// A 3x3 matrix of T (double, or Lanes for four at once), column by column: (i, j) at 3 j + i.
template <typename T>
using Matrix9 = std::array<T, 9>;

/// a b.
template <typename T>
Matrix9<T> product(const Matrix9<T>& a, const Matrix9<T>& b) {
  Matrix9<T> c;
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) {
      c[3 * j + i] = a[i] * b[3 * j] + a[3 + i] * b[3 * j + 1] + a[6 + i] * b[3 * j + 2];
    }
  }
  return c;
}

/// a^T b.
template <typename T>
Matrix9<T> transposedProduct(const Matrix9<T>& a, const Matrix9<T>& b) {
  Matrix9<T> c;
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) {
      c[3 * j + i] =
          a[3 * i] * b[3 * j] + a[3 * i + 1] * b[3 * j + 1] + a[3 * i + 2] * b[3 * j + 2];
    }
  }
  return c;
}

/// Whether a comparison held anywhere.
inline bool any(bool held) {
  return held;
}
inline bool any(LaneMask held) {
  for (int lane = 0; lane < kLaneCount; ++lane) {
    if (held[lane] != 0) return true;
  }
  return false;
}

/// The square root, lane by lane.
inline double squareRoot(double x) {
  return std::sqrt(x);
}
inline Lanes squareRoot(Lanes x) {
  Lanes root;
  for (int lane = 0; lane < kLaneCount; ++lane) root[lane] = std::sqrt(x[lane]);
  return root;
}

}  // namespace ambf_like::detail
