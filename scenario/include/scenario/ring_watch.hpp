#pragma once
// Watches the six rings through a run, as a ScenePerception shows them: how high each rose,
// its volume's extremes (when the perception can tell), and whether it was lost (a non-finite
// pose, volume off by more than 20 %, fallen through the board).

#include <array>

#include "bridge/scene_perception.hpp"
#include "scenario/peg_layout.hpp"
#include "scenario/peg_transfer_result.hpp"

namespace scenario {

/// The limits a ring must stay within to count as whole.
struct RingIntegrity {
  double volume_tolerance = 0.20;  ///< |volume / rest volume - 1|
  double below_board = 0.003;      ///< its bottom this far under the board top: tunnelled
};

/// Tracks the rings' outcomes; call observe() after every manual-loop iteration.
class RingWatch {
 public:
  explicit RingWatch(const PegLayout& layout, RingIntegrity limits = {});

  void observe(const bridge::ScenePerception& scene);
  /// The final outcomes: each ring placed if whole and resting on its target post.
  std::array<RingOutcome, 6> finish(const bridge::ScenePerception& scene) const;
  std::size_t lost() const;

 private:
  PegLayout layout_;
  RingIntegrity limits_;
  std::array<RingOutcome, 6> outcomes_;
};

}  // namespace scenario
