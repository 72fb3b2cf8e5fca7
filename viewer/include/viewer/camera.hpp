#pragma once
// An orbit camera about a target point (z up): the view a viewer window and a snapshot share.

#include <Eigen/Geometry>
#include <optional>

namespace viewer {

/// Orbit/pan/zoom camera; angles in radians.
struct Camera {
  Eigen::Vector3d target = Eigen::Vector3d::Zero();
  double yaw = -2.0;   ///< of the eye about the target, from +x towards +y
  double pitch = 0.5;  ///< of the eye above the target's horizontal plane
  double distance = 1.0;
  double fov_y = 0.6;  ///< vertical field of view

  /// Looks at the box's centre from far enough to see all of it.
  static Camera framing(const Eigen::AlignedBox3d& box);

  Eigen::Vector3d eye() const;
  Eigen::Matrix4d view() const;
  Eigen::Matrix4d projection(double aspect) const;
  double nearPlane() const { return distance * 0.01; }
  double farPlane() const { return distance * 20.0; }
  /// Where a world point lands in a width x height image (origin top left), if in front.
  std::optional<Eigen::Vector2d> toPixel(const Eigen::Vector3d& point, int width, int height) const;

  /// Mouse moves in pixels: turn about the target, slide the target, or move closer.
  void orbit(double dx, double dy);
  void pan(double dx, double dy, int height);
  void zoom(double steps);
};

}  // namespace viewer
