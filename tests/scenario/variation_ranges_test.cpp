// The ranges a randomised peg-transfer scene is drawn from, read from YAML: what a file sets,
// what it may not, and draws that stay within what it set.

#include <gtest/gtest.h>

#include "common/load_error.hpp"
#include "harness/temp_dir.hpp"
#include "scenario/scene_variation.hpp"

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
  EXPECT_NE(errorFor("board_friction: [nan, 1]\n").find("board_friction"), std::string::npos);
  EXPECT_NE(errorFor("[1, 2]\n").find("ranges.yaml"), std::string::npos);
  EXPECT_NE(errorFor("ring_kDF: [0.9, 0.4]\n").find("ranges.yaml"), std::string::npos);
  EXPECT_EQ(errorFor("{}\n"), "");
}

}  // namespace
