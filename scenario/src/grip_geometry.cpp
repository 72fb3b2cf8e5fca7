#include "scenario/grip_geometry.hpp"

#include <algorithm>
#include <cmath>

namespace scenario {

double wallSqueeze(const PinchedWall& wall, double angle) {
  // Depth d below the jaw axis; the wall's outer side at depth d lies at y_out(d) from the inner
  // jaw's face, the outer jaw's face at d tan(angle).
  const double centre_depth = wall.pivot_above + wall.half_height;
  const double centre_across = wall.gap + wall.half_width;
  constexpr int kSamples = 400;
  double deepest = 0.0;
  for (int i = 0; i <= kSamples; ++i) {
    const double d = wall.jaw_length * i / kSamples;
    const double u = (d - centre_depth) / wall.half_height;
    if (std::abs(u) > 1.0) continue;
    const double outer = centre_across + wall.half_width * std::sqrt(1.0 - u * u);
    deepest = std::max(deepest, outer - d * std::tan(angle));
  }
  return deepest;
}

double squeezingAngle(const PinchedWall& wall, double squeeze) {
  double closed = 0.0, open = M_PI / 2 - 1e-6;  // wallSqueeze(closed) >= squeeze > at open
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (closed + open);
    (wallSqueeze(wall, mid) >= squeeze ? closed : open) = mid;
  }
  return 0.5 * (closed + open);
}

}  // namespace scenario
