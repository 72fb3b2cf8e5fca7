#pragma once
// Seeded variations of the peg-transfer scene for randomised batches: peg start poses, the
// rings' silicone and friction, board friction, each drawn from a stated range.

#include <array>
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "ambf_like/scene_spec.hpp"

namespace scenario {

/// The ranges the draws come from.
struct VariationRanges {
  double ring_offset = 0.001;                ///< start position jitter radius (m)
  std::array<double, 2> ring_kDF{0.4, 0.9};  ///< soft-rigid friction factor
  /// The rings' Shore A hardness, drawn uniformly; their Young's modulus follows by Ruess'
  /// relation (0.68-2.0 MPa): the casting silicones and PDMS a ring set is made of
  /// (../shared/reference/soft-materials.md).
  std::array<double, 2> ring_shore_a{20.0, 40.0};
  std::array<double, 2> board_friction{0.4, 0.8};
  /// Draw each value at its range's low or high end (a fair coin each), every ring's start at
  /// the full offset radius: a robustness check at the edges of what a policy was trained on.
  bool at_edges = false;
};

/// The ranges a YAML file states, each key optional (the others keep their defaults):
/// `ring_offset: 0.001` (m), `ring_kDF`, `ring_shore_a`, `board_friction`: [low, high];
/// `at_edges: true` draws at the ranges' ends (VariationRanges::at_edges). Throws
/// common::LoadError naming the file, line and key for an unknown key, a value that is not
/// one, or one out of what it can be (kDF within 0..1, Shore A within 0..100, frictions and the
/// offset >= 0, low <= high).
VariationRanges readVariationRanges(const std::filesystem::path& file);

/// One draw: everything a run varies.
struct SceneVariation {
  std::uint64_t seed = 0;
  bool nominal = true;               ///< the scene as designed, nothing varied
  std::array<double, 6> ring_yaw{};  ///< rad, about the ring's own axis
  std::array<Eigen::Vector2d, 6> ring_offset{};
  double kDF = 0.8, board_friction = 0.6;
  double ring_shore_a = 30.0;
  /// The rings' Young's modulus (Pa) from their hardness, by Ruess' relation.
  double ringYoungsModulus() const;

  /// Draws from `ranges` with `seed` (the same seed, the same draw, wherever libstdc++ runs it).
  static SceneVariation draw(std::uint64_t seed, const VariationRanges& ranges = {});
  /// Applies to the peg-transfer scene's rings (soft bodies ring1..ring6) and board.
  void apply(ambf_like::SceneSpec& scene) const;
  nlohmann::json json() const;
};

}  // namespace scenario
