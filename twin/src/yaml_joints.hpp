#pragma once
// Reading per-joint value lists from bridge configuration files, with file/line/key errors.

#include <sstream>
#include <string>

#include "common/yaml_view.hpp"
#include "raven/arm.hpp"
#include "twin/vocabulary.hpp"

namespace twin {

/// A list of exactly 7 numbers, each >= `minimum` (> `minimum` when `strictly_above`).
inline raven::ArmJoints readJoints(const common::YamlView& node, double minimum,
                                   bool strictly_above) {
  const auto values = node.asDoubleList(raven::kJointCount);
  for (double v : values) {
    if (strictly_above ? v <= minimum : v < minimum) {
      std::ostringstream bound;
      bound << minimum;
      node.fail(std::string("every value must be ") + (strictly_above ? "> " : ">= ") +
                bound.str());
    }
  }
  return Eigen::Map<const raven::ArmJoints>(values.data());
}

}  // namespace twin
