#include "analysis/error_windows.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace analysis {

std::vector<ErrorWindow> errorWindows(const std::vector<ActuatorTrace>& twin,
                                      const std::vector<ActuatorTrace>& physical,
                                      ActuatorSignal signal, raven::Arm arm, int joint,
                                      std::size_t rows_per_window) {
  if (physical.empty() || (twin.size() != 1 && twin.size() != physical.size())) {
    throw std::invalid_argument("one twin trace, or one per physical trial");
  }
  if (joint < 0 || joint >= raven::kJointCount) {
    throw std::invalid_argument("a joint index is 0.." + std::to_string(raven::kJointCount - 1));
  }
  if (rows_per_window == 0) throw std::invalid_argument("a window has at least one row");
  std::size_t rows = physical.front().rows();
  for (std::size_t i = 0; i < physical.size(); ++i) {
    rows = std::min({rows, physical[i].rows(), twin[twin.size() == 1 ? 0 : i].rows()});
  }
  const auto a = raven::slot(arm);
  std::vector<double> per_row(rows, 0.0);  // summed over the trials
  for (std::size_t i = 0; i < physical.size(); ++i) {
    const ActuatorTrace& t = twin[twin.size() == 1 ? 0 : i];
    for (std::size_t r = 0; r < rows; ++r) {
      per_row[r] += std::abs(logged(t.arms[a][r], signal)(joint) -
                             logged(physical[i].arms[a][r], signal)(joint));
    }
  }
  double total = 0.0;
  for (double d : per_row) total += d;
  std::vector<ErrorWindow> windows;
  for (std::size_t first = 0; first < rows; first += rows_per_window) {
    ErrorWindow w;
    w.first_row = first;
    w.last_row = std::min(rows, first + rows_per_window) - 1;
    w.start = physical.front().time[w.first_row];
    w.end = physical.front().time[w.last_row];
    double sum = 0.0;
    for (std::size_t r = w.first_row; r <= w.last_row; ++r) sum += per_row[r];
    w.share = total > 0.0 ? sum / total : 0.0;
    w.mean = sum / static_cast<double>((w.last_row - w.first_row + 1) * physical.size());
    windows.push_back(w);
  }
  return windows;
}

}  // namespace analysis
