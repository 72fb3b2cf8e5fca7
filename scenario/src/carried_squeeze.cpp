#include "scenario/carried_squeeze.hpp"

#include <algorithm>

namespace scenario {

void CarriedSqueeze::record(const std::string& ring, const bridge::GrasperForces& forces) {
  auto& jaws = samples_[ring];
  for (std::size_t jaw = 0; jaw < 2; ++jaw) jaws[jaw].push_back(forces.jaws[jaw].normal.norm());
}

std::array<double, 2> CarriedSqueeze::median(const std::string& ring) const {
  std::array<double, 2> out{0.0, 0.0};
  const auto it = samples_.find(ring);
  if (it == samples_.end()) return out;
  for (std::size_t jaw = 0; jaw < 2; ++jaw) {
    std::vector<double> values = it->second[jaw];
    if (values.empty()) continue;
    const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    out[jaw] = *middle;
  }
  return out;
}

}  // namespace scenario
