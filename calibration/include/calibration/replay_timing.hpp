#pragma once
// The timing of the controller that made physical recordings, measured from them: how much
// longer each manual-loop iteration took on the robot than its command steps alone.

#include <vector>

#include "analysis/trial_set.hpp"

namespace calibration {

/// The median, over every physical trial and row, of the physical row spacing minus the spacing
/// of `twin` (a replay of the same inputs with no overhead, so its rows are exactly the steps'
/// time apart). Robust to the robot's occasional long pauses. Seconds, >= 0.
double measureIterationOverhead(const analysis::Trial& twin,
                                const std::vector<analysis::Trial>& physical);

}  // namespace calibration
