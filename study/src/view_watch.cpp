#include "study/view_watch.hpp"

#include <cmath>

namespace study {

ViewWatch::ViewWatch(const viewer::Camera& camera, int width, int height)
    : camera_(camera), width_(width), height_(height) {}

bool ViewWatch::sees(const Eigen::Vector3d& point) const {
  const auto pixel = camera_.toPixel(point, width_, height_);
  return pixel && pixel->x() >= 0.0 && pixel->x() <= width_ && pixel->y() >= 0.0 &&
         pixel->y() <= height_;
}

void ViewWatch::observe(double time, const raven::PerArm<Eigen::Vector3d>& jaws, EventLog& events) {
  for (std::size_t a = 0; a < 2; ++a) {
    const bool out = !sees(jaws[a]);
    if (out != out_[a]) events.add(time, out ? "out_of_view" : "in_view", static_cast<int>(a));
    out_[a] = out;
  }
}

viewer::Camera cameraHolding(const Eigen::Vector3d& centre, double radius) {
  viewer::Camera c;
  c.target = centre;
  // The ball fills the picture's height: its tangent cone's half-angle is half the field of view.
  c.distance = radius / std::sin(c.fov_y / 2);
  return c;
}

}  // namespace study
