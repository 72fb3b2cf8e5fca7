#pragma once
// Seeded variations of the peg-transfer scene for randomised batches: peg start poses, peg
// friction and softness, board friction, each drawn uniformly from a stated range.

#include <array>
#include <cstdint>
#include <nlohmann/json.hpp>

#include "ambf_like/scene_spec.hpp"

namespace scenario {

/// The ranges the draws come from.
struct VariationRanges {
  double peg_offset = 0.001;                 ///< start position jitter radius (m)
  std::array<double, 2> peg_kDF{0.4, 0.9};   ///< soft-rigid friction factor
  std::array<double, 2> peg_kLST{0.7, 1.0};  ///< link stiffness
  std::array<double, 2> peg_kMT{0.05, 0.2};  ///< shape matching
  std::array<double, 2> board_friction{0.4, 0.8};
};

/// One draw: everything a run varies.
struct SceneVariation {
  std::uint64_t seed = 0;
  bool nominal = true;              ///< the scene as designed, nothing varied
  std::array<double, 6> peg_yaw{};  ///< rad, about the peg's own axis
  std::array<Eigen::Vector2d, 6> peg_offset{};
  double kDF = 0.8, kLST = 1.0, kMT = 0.1, board_friction = 0.6;

  /// Draws from `ranges` with `seed` (the same seed, the same draw, wherever libstdc++ runs it).
  static SceneVariation draw(std::uint64_t seed, const VariationRanges& ranges = {});
  /// Applies to the peg-transfer scene's pegs (soft bodies peg1..peg6) and board.
  void apply(ambf_like::SceneSpec& scene) const;
  nlohmann::json json() const;
};

}  // namespace scenario
