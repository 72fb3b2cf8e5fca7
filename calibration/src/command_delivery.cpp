#include "calibration/command_delivery.hpp"

#include <algorithm>
#include <stdexcept>

#include "analysis/metrics.hpp"

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
      const auto& t = twin[i].arms[a];
      const auto& p = physical[i].arms[a];
      for (int j = raven::kShoulder; j <= raven::kInsertion; ++j) {
        double tp = 0.0, tt = 0.0;
        for (std::size_t r = 0; r < rows; ++r) {
          const double dt = t[r].joint_setpoint(j) - t[0].joint_setpoint(j);
          tp += dt * (p[r].joint_setpoint(j) - p[0].joint_setpoint(j));
          tt += dt * dt;
        }
        if (tt > 0.0) slopes.push_back(tp / tt);
      }
    }
  }
  if (slopes.empty()) return 1.0;  // nothing moved: nothing to tell
  return std::clamp(analysis::median(std::move(slopes)), 0.5, 1.0);
}

}  // namespace calibration
