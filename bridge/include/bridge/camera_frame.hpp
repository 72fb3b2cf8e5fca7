#pragma once
// One image from a camera (a simulated view or the robot's own camera), colour or depth, as a
// value: what a policy that sees reads. No simulator or ROS needed to hold one.

#include <cstdint>
#include <vector>

namespace bridge {

/// An RGB image (rows top first, 3 bytes a pixel) or a depth image (one float a pixel: m along
/// the camera's axis, +infinity where nothing is seen): one of `rgb` and `depth` is filled.
struct CameraFrame {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;
  std::vector<float> depth;
  double time = 0.0;  ///< the source's stamp (s): platform time for the twin node

  bool isDepth() const { return !depth.empty(); }
};

}  // namespace bridge
