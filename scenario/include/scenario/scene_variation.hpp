#pragma once
// Seeded variations of the peg-transfer scene for randomised batches: peg start poses, the
// rings' silicone and friction, board friction, the motors' fitted mechanics and the cameras'
// look (their pose, the lights, the colours), each drawn from a stated range.

#include <array>
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "ambf_like/scene_spec.hpp"
#include "twin/motor_dynamics.hpp"

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
  /// The motors' mechanics (motor-level actuation): each fitted value drawn uniformly within
  /// this many of its standard deviations (the calibration's own, from the Fisher information:
  /// CalibrationProfile::uncertainty) of the fit, kept within what it can be. 0: as fitted.
  double actuation_sd = 1.0;
  /// The cameras (images only): each one's aim point moves within +/- camera_shift (m) on each
  /// axis and turns within +/- camera_turn (rad) in yaw and in pitch, its distance is scaled
  /// within camera_distance: a camera mounted again by hand. The lights' brightness is scaled
  /// within `light`, each colour channel of the rings and of every other surface within `tint`.
  /// Unvaried by default (the shipped image policy saw one look): scenario/ranges/looks.yaml
  /// varies them.
  double camera_shift = 0.0;
  double camera_turn = 0.0;
  std::array<double, 2> camera_distance{1.0, 1.0};
  std::array<double, 2> light{1.0, 1.0};
  std::array<double, 2> tint{1.0, 1.0};
  /// The depth images as a stereo RGB-D camera reads them (viewer::StereoDepthErrors): its RMS
  /// error at 1 m (m), its scale bias (a factor) and its baseline (m). Exact by default;
  /// scenario/ranges/depth.yaml varies them.
  std::array<double, 2> depth_noise{0.0, 0.0};
  std::array<double, 2> depth_scale{1.0, 1.0};
  std::array<double, 2> depth_baseline{0.0, 0.0};
  /// Draw each value at its range's low or high end (a fair coin each), every ring's start at
  /// the full offset radius: a robustness check at the edges of what a policy was trained on.
  bool at_edges = false;
};

/// The ranges a YAML file states, each key optional (the others keep their defaults):
/// `ring_offset: 0.001` (m), `ring_kDF`, `ring_shore_a`, `board_friction`: [low, high];
/// `actuation_sd: 1` (standard deviations of the fit, >= 0); `camera_shift` (m), `camera_turn`
/// (rad), both >= 0; `camera_distance`, `light`, `tint`: [low, high] factors > 0;
/// `depth_noise` (m), `depth_scale`, `depth_baseline` (m): [low, high], >= 0 (the scale > 0);
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
  double actuation_sd = 0.0;  ///< the range the motors' mechanics were drawn from
  /// Per arm and mechanics field (MotorMechanics::kNames), each motor's draw in [-1, 1]: the
  /// value is the fit plus this times actuation_sd times its standard deviation.
  raven::PerArm<
      std::array<std::array<double, raven::kJointCount>, twin::MotorMechanics::kNames.size()>>
      actuation_draw{};
  /// The cameras' look (VariationRanges): how each camera moved, the lights, the colours.
  Eigen::Vector3d camera_shift = Eigen::Vector3d::Zero();
  double camera_yaw = 0.0, camera_pitch = 0.0, camera_distance = 1.0;
  double light = 1.0;
  Eigen::Vector3d ring_tint = Eigen::Vector3d::Ones(), body_tint = Eigen::Vector3d::Ones();
  /// How the cameras' depth images are read (viewer::StereoDepthErrors): the RMS error at 1 m
  /// (m), the scale bias, the stereo baseline (m); exact by default.
  double depth_noise = 0.0, depth_scale = 1.0, depth_baseline = 0.0;
  /// The rings' Young's modulus (Pa) from their hardness, by Ruess' relation.
  double ringYoungsModulus() const;

  /// Draws from `ranges` with `seed` (the same seed, the same draw, wherever libstdc++ runs it).
  static SceneVariation draw(std::uint64_t seed, const VariationRanges& ranges = {});
  /// Applies to the peg-transfer scene's rings (soft bodies ring1..ring6) and board.
  void apply(ambf_like::SceneSpec& scene) const;
  /// Applies to the motors' fitted mechanics `fit` with their standard deviations `sd`, each
  /// value kept within what it can be (MotorMechanics::kRanges; beyond an open bound, such as an
  /// inertia's 0, it is held halfway between the fit and the bound).
  twin::ArmsMechanics mechanics(const twin::ArmsMechanics& fit,
                                const twin::ArmsMechanics& sd) const;
  nlohmann::json json() const;
};

}  // namespace scenario
