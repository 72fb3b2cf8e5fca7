#include "calibration/command_delivery.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace calibration {

double measureServoDelivery(const std::vector<analysis::ActuatorTrace>& twin,
                            const std::vector<analysis::ActuatorTrace>& physical) {
  if (twin.size() != physical.size() || twin.empty()) {
    throw std::invalid_argument("measureServoDelivery: one twin replay per physical trial");
  }
  std::vector<double> slopes;
  for (std::size_t i = 0; i < twin.size(); ++i) {
    const std::size_t rows = std::min(twin[i].rows(), physical[i].rows());
    for (std::size_t a = 0; a < 2; ++a) {
      const auto& t = twin[i].arms[a].joint_setpoint;
      const auto& p = physical[i].arms[a].joint_setpoint;
      for (int j = raven::kShoulder; j <= raven::kInsertion; ++j) {
        double tp = 0.0, tt = 0.0;
        for (std::size_t r = 0; r < rows; ++r) {
          const double dt = t[r](j) - t[0](j);
          tp += dt * (p[r](j) - p[0](j));
          tt += dt * dt;
        }
        if (tt > 0.0) slopes.push_back(tp / tt);
      }
    }
  }
  if (slopes.empty()) return 1.0;  // nothing moved: nothing to tell
  std::sort(slopes.begin(), slopes.end());
  const std::size_t n = slopes.size();
  const double median = n % 2 ? slopes[n / 2] : 0.5 * (slopes[n / 2 - 1] + slopes[n / 2]);
  return std::clamp(median, 0.5, 1.0);
}

}  // namespace calibration
