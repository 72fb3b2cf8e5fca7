#pragma once
// Watches the six soft pegs through a run: how high each rose, its volume's extremes, and
// whether it was lost (non-finite nodes, volume off by more than 20 %, fallen through the board).

#include <array>

#include "ambf_like/world.hpp"
#include "scenario/peg_layout.hpp"
#include "scenario/peg_transfer_result.hpp"

namespace scenario {

/// The limits a peg must stay within to count as whole.
struct PegIntegrity {
  double volume_tolerance = 0.20;  ///< |volume / rest volume - 1|
  double below_board = 0.003;      ///< lowest node this far under the board top: tunnelled
};

/// Tracks the pegs' outcomes; call observe() after every manual-loop iteration.
class PegWatch {
 public:
  /// Reads the pegs' rest volumes from `world` now (before any step).
  PegWatch(const ambf_like::World& world, const PegLayout& layout, PegIntegrity limits = {});

  void observe();
  /// The final outcomes: each peg placed if whole and resting on its target post.
  std::array<PegOutcome, 6> finish() const;
  std::size_t lost() const;

 private:
  PegLayout layout_;
  PegIntegrity limits_;
  std::array<const ambf_like::SoftBody*, 6> pegs_{};  ///< per job: its peg
  std::array<double, 6> rest_volume_{};
  std::array<PegOutcome, 6> outcomes_;
};

}  // namespace scenario
