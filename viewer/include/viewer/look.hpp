#pragma once
// How a scene's surfaces look when drawn, besides their shapes: the lights' brightness and a
// colour factor for the rigid and the soft bodies (a camera's images varied for learning).

#include <Eigen/Core>

namespace viewer {

/// The drawing's lights and colours relative to the viewer's own (the default changes nothing).
struct Look {
  float light = 1.0f;  ///< the key, fill and ambient lights' brightness, times
  Eigen::Vector3f body_tint = Eigen::Vector3f::Ones();  ///< per channel, every rigid body's colour
  Eigen::Vector3f soft_tint = Eigen::Vector3f::Ones();  ///< per channel, the soft bodies' colour
};

}  // namespace viewer
