#pragma once
// Correlating factors of the cross-platform differences (the paper's Fig. 8): how a joint's
// simulation-minus-physical position difference varies with time, joint position and velocity.

#include <string>
#include <vector>

#include "analysis/lowess.hpp"
#include "analysis/metrics.hpp"

namespace analysis {

enum class Factor { Time, Position, Velocity };
const char* factorName(Factor f);
constexpr Factor kFactors[] = {Factor::Time, Factor::Position, Factor::Velocity};

/// One joint's differences against one factor, pooled over the comparison's trial pairs. The
/// factor is read on the second platform (the physical robot in a T_PS comparison).
struct FactorSamples {
  int column = 0;
  Factor factor = Factor::Time;
  std::vector<double> value;       ///< the factor
  std::vector<double> difference;  ///< a - b, joint position (rad, m)
};

FactorSamples factorSamples(const Comparison& c, int column, Factor factor);

/// What the report says about one joint and factor.
struct FactorCorrelation {
  int column = 0;
  Factor factor = Factor::Time;
  double pearson_difference = 0.0;  ///< r of the signed difference with the factor
  double spearman_magnitude = 0.0;  ///< rho of |difference| with the factor
  std::size_t samples = 0;
  Curve trend;  ///< LOWESS of the difference against the factor
};

FactorCorrelation correlate(const FactorSamples& samples);

}  // namespace analysis
