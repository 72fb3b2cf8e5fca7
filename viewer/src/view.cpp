#include "viewer/view.hpp"

#include <stdexcept>

namespace viewer {

Camera View::at(const std::vector<Eigen::Isometry3d>& body_poses) const {
  if (!follow_body) return camera;
  if (*follow_body >= body_poses.size()) {
    throw std::out_of_range("view '" + name + "' follows body " + std::to_string(*follow_body) +
                            " of a world with " + std::to_string(body_poses.size()));
  }
  Camera moved = camera;
  moved.target = body_poses[*follow_body] * camera.target;
  return moved;
}

const View& findView(const std::vector<View>& views, const std::string& name) {
  std::string names;
  for (const View& view : views) {
    if (view.name == name) return view;
    names += (names.empty() ? "" : ", ") + view.name;
  }
  throw std::invalid_argument("no view named '" + name + "' (views: " + names + ")");
}

}  // namespace viewer
