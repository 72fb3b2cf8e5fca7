#pragma once
// Angles folded into [-pi, pi], as std::remainder(angle, 2 pi) does, without its cost for the
// angles already there (every joint reading, every step).

#include <cmath>

namespace common {

/// `angle` moved by whole turns into [-pi, pi]: std::remainder's bits, which for |angle| <= pi
/// are the angle itself (n = round(angle / 2 pi) = 0, ties to even).
inline double wrapToPi(double angle) {
  return std::abs(angle) <= M_PI ? angle : std::remainder(angle, 2.0 * M_PI);
}

}  // namespace common
