#include "calibration/replay_timing.hpp"

#include <algorithm>
#include <cmath>

namespace calibration {

double measureIterationOverhead(const analysis::Trial& twin,
                                const std::vector<analysis::Trial>& physical) {
  std::vector<double> extra;
  for (const auto& trial : physical) {
    const std::size_t rows = std::min(trial.rows(), twin.rows());
    for (std::size_t r = 1; r < rows; ++r) {
      const double d = (trial.time[r] - trial.time[r - 1]) - (twin.time[r] - twin.time[r - 1]);
      if (std::isfinite(d)) extra.push_back(d);
    }
  }
  if (extra.empty()) return 0.0;
  const auto middle = extra.begin() + static_cast<std::ptrdiff_t>(extra.size() / 2);
  std::nth_element(extra.begin(), middle, extra.end());
  return std::max(0.0, *middle);
}

}  // namespace calibration
