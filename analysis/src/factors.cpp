#include "analysis/factors.hpp"

#include <algorithm>
#include <cmath>

namespace analysis {

const char* factorName(Factor f) {
  switch (f) {
    case Factor::Time:
      return "time";
    case Factor::Position:
      return "joint position";
    case Factor::Velocity:
      return "joint velocity";
  }
  return "?";
}

FactorSamples factorSamples(const Comparison& c, int column, Factor factor) {
  FactorSamples s{column, factor, {}, {}};
  const auto col = static_cast<std::size_t>(column);
  forEachPair(c, [&](const Trial& a, const Trial& b) {
    const std::size_t rows = std::min(a.rows(), b.rows());
    for (std::size_t r = 0; r < rows; ++r) {
      const double d = a.position[r][col] - b.position[r][col];
      const double v = factor == Factor::Time       ? b.time[r]
                       : factor == Factor::Position ? b.position[r][col]
                                                    : b.velocity[r][col];
      if (!std::isfinite(d) || !std::isfinite(v)) continue;
      s.value.push_back(v);
      s.difference.push_back(d);
    }
  });
  return s;
}

FactorCorrelation correlate(const FactorSamples& s) {
  FactorCorrelation c;
  c.column = s.column;
  c.factor = s.factor;
  c.samples = s.value.size();
  c.pearson_difference = pearson(s.value, s.difference);
  std::vector<double> magnitude(s.difference.size());
  std::transform(s.difference.begin(), s.difference.end(), magnitude.begin(),
                 [](double d) { return std::abs(d); });
  c.spearman_magnitude = spearman(s.value, magnitude);
  c.trend = lowess(s.value, s.difference);
  return c;
}

}  // namespace analysis
