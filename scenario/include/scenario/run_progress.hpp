#pragma once
// Where a scripted run is, for a progress display.

#include <cstddef>
#include <cstdint>
#include <functional>

namespace ambf_like {
class World;
}

namespace scenario {

/// A run's position: simulated time, and units of work done.
struct RunProgress {
  double sim_time = 0.0;
  std::size_t done = 0;      ///< transfers (or rectangle edges) finished
  std::size_t total = 0;     ///< ... of this many
  std::size_t carrying = 0;  ///< arms between closing on a ring and opening (lift, carry, lower)
};

/// Called after every manual-loop iteration.
using ProgressCallback = std::function<void(const RunProgress&)>;

/// When a run shows its world to an observer.
enum class WorldMoment { Start, Iteration, End };
/// Shown a run's world at a moment; `seed` says which run of a batch it is.
using WorldObserver = std::function<void(const ambf_like::World&, WorldMoment, std::uint64_t seed)>;

}  // namespace scenario
