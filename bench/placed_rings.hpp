#pragma once
// The last line of `python3 -m raven_sim.learn evaluate` ("placed N/M rings; K/E episodes all
// six") read back, for the sections that run a policy.

#include <optional>
#include <string>
#include <vector>

namespace bench {

/// What one evaluation placed.
struct PlacedRings {
  int rings = 0, of = 0;          ///< rings placed, out of six an episode
  int all_six = 0, episodes = 0;  ///< episodes that placed all six
  double percent() const { return of > 0 ? 100.0 * rings / of : 0.0; }
  /// "N/M rings; K/E episodes all six"
  std::string summary() const;
};

/// The evaluation's result from its output's lines, or nothing if no line says it.
std::optional<PlacedRings> placedRingsIn(const std::vector<std::string>& lines);

}  // namespace bench
