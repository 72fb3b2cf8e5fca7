#pragma once
// Checks for the numbers a command line gives, refusing what CLI11's own let through: NaN passes
// CLI::NonNegativeNumber, CLI::PositiveNumber and CLI::Range (every comparison with it is
// false), so `--duration nan` ran a program for ever. Every program's numeric options use these.

#include <CLI/CLI.hpp>
#include <limits>

namespace common {

/// A finite number within [low, high] (a bound at infinity: none on that side).
CLI::Validator finiteWithin(double low, double high);
/// A finite number above `low`.
CLI::Validator finiteAbove(double low);

inline const CLI::Validator kFinite =
    finiteWithin(-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity());
inline const CLI::Validator kFiniteNonNegative =
    finiteWithin(0.0, std::numeric_limits<double>::infinity());
inline const CLI::Validator kFinitePositive = finiteAbove(0.0);

}  // namespace common
