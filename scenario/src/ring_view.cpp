#include "scenario/ring_view.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace scenario {

namespace {

/// Half the vertical extent of the ring (a tube of elliptic section about its centre line) when
/// its axis has vertical component `axis_z`: the support function of the torus, R sin(tilt) +
/// the section's sqrt(a^2 sin^2 + b^2 cos^2).
double halfExtent(const RingDimensions& size, double axis_z) {
  const double c = std::abs(axis_z), s = std::sqrt(std::max(0.0, 1.0 - c * c));
  const double a = size.tube_half_width, b = size.half_height;
  return size.major_radius * s + std::sqrt(a * a * s * s + b * b * c * c);
}

}  // namespace

double RingView::bottom() const {
  return centre().z() - halfExtent(size, axis().z());
}

double RingView::top() const {
  return centre().z() + halfExtent(size, axis().z());
}

Eigen::Vector3d RingView::stationToward(const Eigen::Vector2d& toward) const {
  const Eigen::Vector3d d(toward.x(), toward.y(), 0.0);
  Eigen::Vector3d radial = (d - d.dot(axis()) * axis()).normalized();
  if (size.stations > 0) {  // the vertex of the centre line nearest that side
    const Eigen::Vector3d local = pose.linear().transpose() * radial;
    const double step = 2.0 * M_PI / size.stations;
    const double u = step * std::round(std::atan2(local.y(), local.x()) / step);
    radial = pose.linear() * Eigen::Vector3d(std::cos(u), std::sin(u), 0.0);
  }
  return centre() + size.major_radius * radial;
}

double RingView::postOffset(const Eigen::Vector2d& post) const {
  const Eigen::Vector3d a = axis();
  if (std::abs(a.z()) < 1e-6) return std::numeric_limits<double>::infinity();
  // The point (post, z) with a . (point - centre) = 0.
  const Eigen::Vector2d horizontal = post - centre().head<2>();
  const double dz = -a.head<2>().dot(horizontal) / a.z();
  return Eigen::Vector3d(horizontal.x(), horizontal.y(), dz).norm();
}

bool restsOn(const RingView& ring, const Eigen::Vector2d& post, const BoardGeometry& geometry,
             double tolerance) {
  return ring.finite() && ring.bottom() < geometry.board_top + tolerance && ring.threadedOn(post);
}

}  // namespace scenario
