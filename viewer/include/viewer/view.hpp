#pragma once
// A named camera on a scene (overview, a task area, a grasper): fixed in the world, or riding
// along with a body so a camera on the grasper keeps the jaws in frame.

#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include "viewer/camera.hpp"

namespace viewer {

/// A camera with a name; when it follows a body, its target is a point in that body's frame and
/// its yaw, pitch and distance stay fixed in the world (the picture does not spin with the wrist).
struct View {
  std::string name;
  Camera camera;
  std::optional<std::size_t> follow_body;  ///< a World body index

  /// The camera at these body poses (World body order).
  Camera at(const std::vector<Eigen::Isometry3d>& body_poses) const;
};

/// The view of that name; throws std::invalid_argument listing the names there are.
const View& findView(const std::vector<View>& views, const std::string& name);

}  // namespace viewer
