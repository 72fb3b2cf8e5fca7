#include "viewer/camera.hpp"

#include <algorithm>
#include <cmath>

namespace viewer {

Camera Camera::framing(const Eigen::AlignedBox3d& box) {
  Camera c;
  c.target = box.center();
  const double radius = std::max(0.5 * box.diagonal().norm(), 1e-3);
  c.distance = radius / std::sin(c.fov_y / 2) * 0.6;
  return c;
}

Eigen::Vector3d Camera::eye() const {
  return target + distance * Eigen::Vector3d(std::cos(pitch) * std::cos(yaw),
                                             std::cos(pitch) * std::sin(yaw), std::sin(pitch));
}

Eigen::Matrix4d Camera::view() const {
  const Eigen::Vector3d f = (target - eye()).normalized();
  const Eigen::Vector3d s = f.cross(Eigen::Vector3d::UnitZ()).normalized();
  const Eigen::Vector3d u = s.cross(f);
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<1, 3>(0, 0) = s.transpose();
  m.block<1, 3>(1, 0) = u.transpose();
  m.block<1, 3>(2, 0) = -f.transpose();
  m.block<3, 1>(0, 3) = -m.block<3, 3>(0, 0) * eye();
  return m;
}

Eigen::Matrix4d Camera::projection(double aspect) const {
  const double t = 1.0 / std::tan(fov_y / 2);
  const double n = nearPlane(), f = farPlane();
  Eigen::Matrix4d p = Eigen::Matrix4d::Zero();
  p(0, 0) = t / aspect;
  p(1, 1) = t;
  p(2, 2) = (f + n) / (n - f);
  p(2, 3) = 2 * f * n / (n - f);
  p(3, 2) = -1;
  return p;
}

std::optional<Eigen::Vector2d> Camera::toPixel(const Eigen::Vector3d& point, int width,
                                               int height) const {
  const Eigen::Vector4d clip = projection(static_cast<double>(width) / height) * view() *
                               Eigen::Vector4d(point.x(), point.y(), point.z(), 1.0);
  if (clip.w() <= 0.0) return std::nullopt;
  const Eigen::Vector2d ndc = clip.head<2>() / clip.w();
  return Eigen::Vector2d((ndc.x() + 1) / 2 * width, (1 - ndc.y()) / 2 * height);
}

void Camera::orbit(double dx, double dy) {
  yaw -= dx * 0.01;
  pitch = std::clamp(pitch + dy * 0.01, -1.5, 1.5);
}

void Camera::pan(double dx, double dy, int height) {
  const Eigen::Matrix4d v = view();
  const Eigen::Vector3d right = v.block<1, 3>(0, 0).transpose();
  const Eigen::Vector3d up = v.block<1, 3>(1, 0).transpose();
  const double metres_per_pixel = 2 * distance * std::tan(fov_y / 2) / std::max(height, 1);
  target += (-dx * right + dy * up) * metres_per_pixel;
}

void Camera::zoom(double steps) {
  distance = std::clamp(distance * std::pow(0.9, steps), 1e-3, 1e3);
}

}  // namespace viewer
