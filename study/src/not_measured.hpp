// The value of a metric or statistic its data cannot give (NaN, written as null in JSON).
#pragma once

#include <limits>

namespace study {

/// What a metric or statistic is when its data cannot give it: a task without rings has no
/// rings placed, one sample has no spread.
inline constexpr double kNotMeasured = std::numeric_limits<double>::quiet_NaN();

}  // namespace study
