#include "scenario/grip_geometry.hpp"

#include <algorithm>
#include <cmath>

namespace scenario {

double wallSqueeze(const PinchedWall& wall, double angle) {
  // Depth d below the jaw axis, u = (d - centre) / half_height: the wall's outer side lies at
  // across + half_width sqrt(1 - u^2) from the inner jaw's face, the outer jaw's face at
  // d tan(angle). Their difference is concave in d, so its maximum along the jaw is where its
  // slope is zero (u = -k / sqrt(1 + k^2), k = tan(angle) half_height / half_width), or the
  // nearest end of the stretch of the jaw beside the wall.
  const double centre_depth = wall.pivot_above + wall.half_height;
  const double centre_across = wall.gap + wall.half_width;
  const double from = std::max(0.0, centre_depth - wall.half_height);
  const double to = std::min(wall.jaw_length, centre_depth + wall.half_height);
  if (from > to) return 0.0;  // the jaw ends above the wall
  const double t = std::tan(angle);
  const double k = t * wall.half_height / wall.half_width;
  const double d =
      std::clamp(centre_depth - wall.half_height * k / std::sqrt(1.0 + k * k), from, to);
  const double u = (d - centre_depth) / wall.half_height;
  const double outer = centre_across + wall.half_width * std::sqrt(std::max(0.0, 1.0 - u * u));
  return std::max(0.0, outer - d * t);
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
