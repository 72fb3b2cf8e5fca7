#pragma once
// Where a scripted run is, for a progress display.

#include <cstddef>
#include <functional>

namespace scenario {

/// A run's position: simulated time, and units of work done.
struct RunProgress {
  double sim_time = 0.0;
  std::size_t done = 0;   ///< transfers (or rectangle edges) finished
  std::size_t total = 0;  ///< ... of this many
};

/// Called after every manual-loop iteration.
using ProgressCallback = std::function<void(const RunProgress&)>;

}  // namespace scenario
