#include "analysis/disparity.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace analysis {

JointGroup revoluteJoints() {
  return {"revolute", {0, 1, 5, 6, 7, 8, 9, 13, 14, 15}, 1.0, "rad"};
}

JointGroup prismaticJoints() {
  return {"prismatic", {2, 10}, 1000.0, "mm"};
}

double meanAbsoluteDifference(const controller::RsRecording& a, const controller::RsRecording& b,
                              const JointGroup& group, Quantity quantity) {
  const std::string stem = quantity == Quantity::Position ? "jpos" : "jvel";
  const std::size_t rows = std::min(a.rows.size(), b.rows.size());
  double sum = 0.0;
  std::size_t count = 0;
  for (int joint : group.jpos) {
    const std::size_t ca = a.column(stem + std::to_string(joint));
    const std::size_t cb = b.column(stem + std::to_string(joint));
    for (std::size_t r = 0; r < rows; ++r) {
      const double d = a.rows[r][ca] - b.rows[r][cb];
      if (std::isnan(d)) continue;  // AMBF rows leave some fields empty
      sum += std::abs(d);
      ++count;
    }
  }
  return count ? group.scale * sum / static_cast<double>(count)
               : std::numeric_limits<double>::quiet_NaN();
}

double withinSet(std::span<const controller::RsRecording> set, const JointGroup& group,
                 Quantity quantity) {
  double sum = 0.0;
  int pairs = 0;
  for (std::size_t i = 0; i < set.size(); ++i) {
    for (std::size_t j = i + 1; j < set.size(); ++j) {
      sum += meanAbsoluteDifference(set[i], set[j], group, quantity);
      ++pairs;
    }
  }
  return pairs ? sum / pairs : std::numeric_limits<double>::quiet_NaN();
}

double acrossSets(std::span<const controller::RsRecording> a,
                  std::span<const controller::RsRecording> b, const JointGroup& group,
                  Quantity quantity) {
  double sum = 0.0;
  int pairs = 0;
  for (const auto& x : a) {
    for (const auto& y : b) {
      sum += meanAbsoluteDifference(x, y, group, quantity);
      ++pairs;
    }
  }
  return pairs ? sum / pairs : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace analysis
