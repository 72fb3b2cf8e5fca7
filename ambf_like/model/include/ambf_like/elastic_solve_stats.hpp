#pragma once
// What the implicit solve of a soft body with a material took, summed over its steps.

#include <cstdint>

namespace ambf_like {

/// Counts over a soft body's implicit steps (substeps count as steps): how often the linearly
/// implicit step was not enough and what the backward-Euler iteration then took.
struct ElasticSolveStats {
  std::uint64_t steps = 0;
  std::uint64_t iterations = 0;  ///< solves: steps when every linearly implicit step was kept
  std::uint64_t halvings = 0;    ///< cut-backs of the line search
  /// Steps that ended still gaining energy beyond their tolerance (the iteration's cap or a
  /// step that stopped moving was reached first).
  std::uint64_t energy_gaining = 0;
};

}  // namespace ambf_like
