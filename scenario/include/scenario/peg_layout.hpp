#pragma once
// The peg-transfer scene's layout as the scenario needs it: which peg starts where, where it
// goes, and the ring's dimensions (raven_description/tools/peg_scene.hpp's design values).

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "raven/arm.hpp"
#include "scenario/peg_state.hpp"

namespace scenario {

/// One transfer: the soft body named `peg` from post `from` to post `to`, by `arm`.
struct PegJob {
  std::string peg;
  raven::Arm arm;
  Eigen::Vector2d from, to;
};

/// The ring and board dimensions and the six jobs.
struct PegLayout {
  double ring_radius = 0.008;      ///< centre line
  double tube_half_width = 0.002;  ///< radially
  double ring_height = 0.010;
  PegGeometry geometry;
  /// Left-side pegs by the left arm, right-side by the right: from the start row (y 0.058) to
  /// the target row (y 0.100) straight behind.
  std::array<PegJob, 6> jobs{
      PegJob{"peg1", raven::Arm::Left, {0.266, 0.058}, {0.266, 0.100}},
      PegJob{"peg2", raven::Arm::Left, {0.300, 0.058}, {0.300, 0.100}},
      PegJob{"peg3", raven::Arm::Left, {0.334, 0.058}, {0.334, 0.100}},
      PegJob{"peg4", raven::Arm::Right, {-0.266, 0.058}, {-0.266, 0.100}},
      PegJob{"peg5", raven::Arm::Right, {-0.300, 0.058}, {-0.300, 0.100}},
      PegJob{"peg6", raven::Arm::Right, {-0.334, 0.058}, {-0.334, 0.100}},
  };

  /// The jobs of one arm, in order.
  std::vector<PegJob> jobsOf(raven::Arm arm) const {
    std::vector<PegJob> out;
    for (const PegJob& job : jobs) {
      if (job.arm == arm) out.push_back(job);
    }
    return out;
  }
};

}  // namespace scenario
