#pragma once
// The Raven-II's first three links as its control software weighs them (uw-biorobotics/raven2
// grav_comp.cpp; ../shared/reference/raven2-actuation.md §3): the one source of these values for
// the twin's gravity compensation and for the model's masses.

#include <Eigen/Core>
#include <array>

#include "raven/arm.hpp"

namespace raven::design {

/// Masses and centres of mass of links 1-3 of one arm, each centre in its link's frame of the
/// firmware chain (raven2-kinematics.md §A: frames 1, 2, 3 after DH rows 0, 1, 2).
struct FirmwareLinks {
  std::array<double, 3> mass{0.494, 0.750, 0.231};  ///< kg; link 3 carries the instrument
  std::array<Eigen::Vector3d, 3> centre{};          ///< m; link 3's is its frame's origin

  static FirmwareLinks of(Arm arm) {
    FirmwareLinks links;
    const double side = arm == Arm::Left ? 1.0 : -1.0;  // gold (left) and green mirror
    links.centre[0] = Eigen::Vector3d(0.0065 * side, 0.09775 * side, -0.13771 * side);
    links.centre[1] = Eigen::Vector3d(-0.002, -0.18274, -0.23053 * side);
    links.centre[2] = Eigen::Vector3d::Zero();
    return links;
  }
};

}  // namespace raven::design
