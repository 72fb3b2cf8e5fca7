#pragma once
// One colour image from a camera (a simulated view or the robot's own camera), as a value: what
// a policy that sees reads. No simulator or ROS needed to hold one.

#include <cstdint>
#include <vector>

namespace bridge {

/// An RGB image, rows top first, 3 bytes a pixel.
struct CameraFrame {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;
  double time = 0.0;  ///< the source's stamp (s): platform time for the twin node
};

}  // namespace bridge
