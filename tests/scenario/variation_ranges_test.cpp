// The ranges a randomised peg-transfer scene is drawn from, read from YAML: what a file sets,
// what it may not, and draws that stay within what it set.

#include <gtest/gtest.h>

#include <set>

#include "common/load_error.hpp"
#include "harness/temp_dir.hpp"
#include "scenario/peg_transfer.hpp"
#include "scenario/scene_variation.hpp"
#include "twin/calibration_profile.hpp"

namespace {

using scenario::readVariationRanges;

/// The message readVariationRanges throws for `text`, or "" when it reads it.
std::string errorFor(const std::string& text) {
  harness::TempDir dir;
  try {
    readVariationRanges(dir.write("ranges.yaml", text));
  } catch (const common::LoadError& e) {
    return e.what();
  }
  return "";
}

TEST(VariationRanges, AFileSetsTheRangesItNamesAndKeepsTheOthers) {
  harness::TempDir dir;
  const auto r = readVariationRanges(
      dir.write("ranges.yaml", "ring_shore_a: [25, 35]\nboard_friction: [0.5, 0.5]\n"));
  EXPECT_EQ(r.ring_shore_a, (std::array<double, 2>{25.0, 35.0}));
  EXPECT_EQ(r.board_friction, (std::array<double, 2>{0.5, 0.5}));
  const scenario::VariationRanges shipped;
  EXPECT_EQ(r.ring_kDF, shipped.ring_kDF);
  EXPECT_EQ(r.ring_offset, shipped.ring_offset);
  for (std::uint64_t seed = 1; seed <= 50; ++seed) {
    const auto v = scenario::SceneVariation::draw(seed, r);
    EXPECT_GE(v.ring_shore_a, 25.0);
    EXPECT_LE(v.ring_shore_a, 35.0);
    EXPECT_EQ(v.board_friction, 0.5);
    for (const auto& offset : v.ring_offset) EXPECT_LE(offset.norm(), shipped.ring_offset);
  }
}

TEST(VariationRanges, TheCamerasLookIsDrawnWithinItsRanges) {
  harness::TempDir dir;
  const auto r = readVariationRanges(
      dir.write("look.yaml",
                "camera_shift: 0.002\ncamera_turn: 0.01\nlight: [0.8, 1.2]\ntint: [0.9, 1.1]\n"));
  EXPECT_EQ(r.camera_distance, scenario::VariationRanges{}.camera_distance);
  std::set<double> lights;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const auto v = scenario::SceneVariation::draw(seed, r);
    EXPECT_LE(v.camera_shift.cwiseAbs().maxCoeff(), 0.002);
    EXPECT_LE(std::abs(v.camera_yaw), 0.01);
    EXPECT_LE(std::abs(v.camera_pitch), 0.01);
    EXPECT_GE(v.light, 0.8);
    EXPECT_LE(v.light, 1.2);
    EXPECT_GE(std::min(v.ring_tint.minCoeff(), v.body_tint.minCoeff()), 0.9);
    EXPECT_LE(std::max(v.ring_tint.maxCoeff(), v.body_tint.maxCoeff()), 1.1);
    lights.insert(v.light);
    EXPECT_EQ(v.json()["light"], v.light);
    // The look changes no physics: the same seed's scene and motors with or without it.
    const auto plain = scenario::SceneVariation::draw(seed, {});
    EXPECT_EQ(v.json()["ring_yaw_rad"], plain.json()["ring_yaw_rad"]);
    EXPECT_EQ(v.json()["actuation_draw"], plain.json()["actuation_draw"]);
  }
  EXPECT_EQ(lights.size(), 20u);
  EXPECT_TRUE(scenario::SceneVariation{}.camera_shift.isZero());  // the nominal scene's look
  EXPECT_EQ(scenario::SceneVariation{}.light, 1.0);
  // The shipped ranges keep one look (the shipped image policy saw one); looks.yaml varies it,
  // and edges.yaml takes it to its ends.
  const auto unvaried = scenario::SceneVariation::draw(7, {});
  EXPECT_TRUE(unvaried.camera_shift.isZero());
  EXPECT_EQ(unvaried.light, 1.0);
  EXPECT_EQ(unvaried.ring_tint, Eigen::Vector3d::Ones());
  const auto looks = readVariationRanges(std::string(RAVEN_RANGES_DIR) + "/looks.yaml");
  EXPECT_GT(looks.camera_turn, 0.0);
  EXPECT_LT(looks.light[0], looks.light[1]);
  const auto edges = readVariationRanges(std::string(RAVEN_RANGES_DIR) + "/edges.yaml");
  EXPECT_TRUE(edges.at_edges);
  EXPECT_EQ(edges.camera_turn, looks.camera_turn);
  EXPECT_EQ(edges.tint, looks.tint);
  EXPECT_EQ(edges.actuation_sd, scenario::VariationRanges{}.actuation_sd);
}

TEST(VariationRanges, TheDepthCamerasErrorsAreDrawnWithinTheirRangesAndChangeNothingElse) {
  harness::TempDir dir;
  const auto r =
      readVariationRanges(dir.write("depth.yaml",
                                    "depth_noise: [0.001, 0.004]\ndepth_scale: [0.98, 1.02]\n"
                                    "depth_baseline: [0.018, 0.055]\n"));
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const auto v = scenario::SceneVariation::draw(seed, r);
    EXPECT_GE(v.depth_noise, 0.001);
    EXPECT_LE(v.depth_noise, 0.004);
    EXPECT_GE(v.depth_scale, 0.98);
    EXPECT_LE(v.depth_scale, 1.02);
    EXPECT_GE(v.depth_baseline, 0.018);
    EXPECT_LE(v.depth_baseline, 0.055);
    EXPECT_EQ(v.json()["depth_scale"], v.depth_scale);
    // Drawn last: the same seed's scene, motors and look as without them.
    auto same = v.json(), plain = scenario::SceneVariation::draw(seed, {}).json();
    for (const char* key : {"depth_noise_m", "depth_scale", "depth_baseline_m"}) {
      same.erase(key);
      plain.erase(key);
    }
    EXPECT_EQ(same, plain);
  }
  // Exact depth unless a file says otherwise.
  const auto shipped = scenario::SceneVariation::draw(3, {});
  EXPECT_EQ(shipped.depth_noise, 0.0);
  EXPECT_EQ(shipped.depth_scale, 1.0);
  EXPECT_EQ(shipped.depth_baseline, 0.0);
  const auto depth = readVariationRanges(std::string(RAVEN_RANGES_DIR) + "/depth.yaml");
  EXPECT_TRUE(depth.at_edges);
  EXPECT_GT(depth.depth_noise[1], 0.0);
  EXPECT_NE(errorFor("depth_noise: [-0.001, 0.002]\n").find("depth_noise"), std::string::npos);
  EXPECT_NE(errorFor("depth_scale: [0, 1]\n").find("depth_scale"), std::string::npos);
}

TEST(VariationRanges, AtTheEdgesEveryValueIsAnEndOfItsRangeAndBothEndsComeUp) {
  harness::TempDir dir;
  const auto r = readVariationRanges(dir.write("edges.yaml", "at_edges: true\n"));
  ASSERT_TRUE(r.at_edges);
  int high_shore = 0;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const auto v = scenario::SceneVariation::draw(seed, r);
    EXPECT_TRUE(v.kDF == r.ring_kDF[0] || v.kDF == r.ring_kDF[1]) << v.kDF;
    EXPECT_TRUE(v.ring_shore_a == r.ring_shore_a[0] || v.ring_shore_a == r.ring_shore_a[1]);
    EXPECT_TRUE(v.board_friction == r.board_friction[0] || v.board_friction == r.board_friction[1]);
    EXPECT_TRUE(v.light == r.light[0] || v.light == r.light[1]);
    EXPECT_EQ(std::abs(v.camera_yaw), r.camera_turn);
    for (const auto& offset : v.ring_offset) EXPECT_NEAR(offset.norm(), r.ring_offset, 1e-12);
    high_shore += v.ring_shore_a == r.ring_shore_a[1];
  }
  EXPECT_GT(high_shore, 2);  // a fair coin: both ends in 20 draws
  EXPECT_LT(high_shore, 18);
  EXPECT_NE(errorFor("at_edges: sometimes\n").find("at_edges"), std::string::npos);
}

TEST(VariationRanges, ABadFileIsAnErrorNamingTheFileAndTheKey) {
  EXPECT_NE(errorFor("ring_shore_a: [25, 35]\nring_colour: [0, 1]\n").find("ring_colour"),
            std::string::npos);
  EXPECT_NE(errorFor("ring_kDF: [0.9, 0.4]\n").find("ring_kDF"), std::string::npos);
  EXPECT_NE(errorFor("ring_kDF: [0.4, 1.5]\n").find("is not a range within [0, 1]"),
            std::string::npos);
  EXPECT_NE(errorFor("ring_shore_a: [25]\n").find("ring_shore_a"), std::string::npos);
  EXPECT_NE(errorFor("ring_offset: -0.001\n").find("ring_offset"), std::string::npos);
  // A ring starts around its post: 6 mm hole, 2.5 mm post (1e300 made the state non-finite).
  EXPECT_NE(errorFor("ring_offset: 1e300\n").find("at most 0.0035 m"), std::string::npos);
  EXPECT_NE(errorFor("ring_offset: 0.0036\n").find("off its post"), std::string::npos);
  EXPECT_EQ(errorFor("ring_offset: 0.0035\n"), "");
  EXPECT_NE(errorFor("actuation_sd: -1\n").find("actuation_sd"), std::string::npos);
  EXPECT_NE(errorFor("actuation_sd: .nan\n").find("actuation_sd"), std::string::npos);
  EXPECT_NE(errorFor("camera_turn: -0.1\n").find("camera_turn"), std::string::npos);
  EXPECT_NE(errorFor("tint: [0, 1]\n").find("tint"), std::string::npos);
  EXPECT_NE(errorFor("light: [1.3, 0.7]\n").find("light"), std::string::npos);
  EXPECT_NE(errorFor("board_friction: [nan, 1]\n").find("board_friction"), std::string::npos);
  EXPECT_NE(errorFor("[1, 2]\n").find("ranges.yaml"), std::string::npos);
  EXPECT_NE(errorFor("ring_kDF: [0.9, 0.4]\n").find("ranges.yaml"), std::string::npos);
  EXPECT_EQ(errorFor("{}\n"), "");
}

/// Whether every fitted value of `drawn` lies within `sds` of its standard deviations of the fit
/// (`at_edge`: exactly that far, unless held at 0), and how many differ from the fit.
int drawnWithin(const twin::ArmsMechanics& drawn, const twin::CalibrationProfile& fit, double sds,
                bool at_edge) {
  int moved = 0;
  for (std::size_t a = 0; a < 2; ++a) {
    for (std::size_t k = 0; k < twin::MotorMechanics::kNames.size(); ++k) {
      for (int i = 0; i < raven::kJointCount; ++i) {
        const double change = drawn[a].field(k)(i) - fit.mechanics[a].field(k)(i);
        const double reach = sds * fit.uncertainty[a].field(k)(i);
        if (at_edge && drawn[a].field(k)(i) != 0.0) {  // else held at its bound (a friction)
          EXPECT_NEAR(std::abs(change), reach, 1e-12 + 1e-9 * reach)
              << twin::MotorMechanics::kNames[k];
        } else {
          EXPECT_LE(std::abs(change), reach * (1 + 1e-12)) << twin::MotorMechanics::kNames[k];
        }
        moved += change != 0.0;
      }
    }
  }
  return moved;
}

TEST(VariationRanges, TheMotorsMechanicsAreDrawnWithinTheCalibrationsStandardDeviations) {
  const auto fit = twin::CalibrationProfile::shipped();
  scenario::VariationRanges ranges;
  ASSERT_EQ(ranges.actuation_sd, 1.0);  // the shipped range: the fit's own uncertainty
  std::set<double> shoulder_inertias;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const auto v = scenario::SceneVariation::draw(seed, ranges);
    const twin::ArmsMechanics drawn = v.mechanics(fit.mechanics, fit.uncertainty);
    // Of the 62 values the fit gives a deviation (not the offsets: the shipped fit has none),
    // some at 0 (a jaw's load friction) are held there when drawn below it.
    EXPECT_GE(drawnWithin(drawn, fit, 1.0, false), 56);
    shoulder_inertias.insert(drawn[0].inertia(0));
    // The twin a run builds drives its motors with them.
    scenario::PegTransferOptions run;
    const twin::TwinOptions twin = scenario::pegTransferTwin(run, v);
    ASSERT_TRUE(twin.motors.has_value());
    EXPECT_EQ((*twin.motors)[1].coulomb, drawn[1].coulomb);
  }
  EXPECT_EQ(shoulder_inertias.size(), 20u);
  // The nominal scene, and a range of 0, keep the fit.
  EXPECT_EQ(drawnWithin(scenario::SceneVariation{}.mechanics(fit.mechanics, fit.uncertainty), fit,
                        0.0, true),
            0);
  harness::TempDir dir;
  const auto none = readVariationRanges(dir.write("none.yaml", "actuation_sd: 0\n"));
  EXPECT_EQ(
      drawnWithin(scenario::SceneVariation::draw(3, none).mechanics(fit.mechanics, fit.uncertainty),
                  fit, 0.0, true),
      0);
  // At the edges every value is the fit plus or minus the range.
  const auto edges =
      readVariationRanges(dir.write("edges.yaml", "at_edges: true\nactuation_sd: 2\n"));
  drawnWithin(scenario::SceneVariation::draw(4, edges).mechanics(fit.mechanics, fit.uncertainty),
              fit, 2.0, true);
  // The scene a seed draws does not depend on the motors' range.
  EXPECT_EQ(scenario::SceneVariation::draw(5, none).json()["ring_yaw_rad"],
            scenario::SceneVariation::draw(5, ranges).json()["ring_yaw_rad"]);
  // However wide the range, every value stays one the motors can have.
  scenario::VariationRanges wide;
  wide.actuation_sd = 1e6;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const auto drawn =
        scenario::SceneVariation::draw(seed, wide).mechanics(fit.mechanics, fit.uncertainty);
    for (raven::Arm arm : raven::kArms) {
      EXPECT_EQ(drawn[raven::slot(arm)].invalidReason(), "") << seed;
      EXPECT_TRUE((drawn[raven::slot(arm)].inertia.array() >=
                   0.5 * fit.mechanics[raven::slot(arm)].inertia.array())
                      .all());
    }
  }
}

}  // namespace
