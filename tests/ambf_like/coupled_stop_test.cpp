// A stop on a sum of joint coordinates (World::addCoupledStop), checked against the statics of a
// two-link chain turning in the horizontal plane (gravity does not turn it).

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "test_files.hpp"

namespace {

/// Two 0.1 m links in a chain, both hinged about the vertical z; the elbow starts at `elbow`.
std::unique_ptr<test_support::Simulation> twoLinkChain(const test_support::TempDir& dir,
                                                       ambf_like::Articulation articulation) {
  const std::string link =
      "  mass: 0.2\n  collision shape: BOX\n  collision geometry: {x: 0.1, y: 0.01, z: 0.01}\n"
      "  damping: {linear: 0, angular: 0}\n";
  const std::string hinge =
      "  parent axis: {x: 0, y: 0, z: 1}\n  child axis: {x: 0, y: 0, z: 1}\n  type: continuous\n"
      "  child pivot: {x: -0.05, y: 0, z: 0}\n";
  const auto model = dir.write(
      "chain.yaml",
      "bodies: [BODY anchor, BODY upper, BODY lower]\njoints: [JOINT shoulder, JOINT elbow]\n"
      "ignore inter-collision: true\n"
      "BODY anchor: {mass: 0, collision shape: BOX, collision geometry: {x: 0.02, y: 0.02, z: "
      "0.02}}\n"
      "BODY upper:\n" +
          link + "  location: {position: {x: 0.05, y: 0, z: 0}}\nBODY lower:\n" + link +
          "  location: {position: {x: 0.15, y: 0, z: 0}}\n"
          "JOINT shoulder:\n  parent: BODY anchor\n  child: BODY upper\n  parent pivot: {x: 0, y: "
          "0, z: 0}\n" +
          hinge +
          "JOINT elbow:\n  parent: BODY upper\n  child: BODY lower\n  parent pivot: {x: 0.05, y: "
          "0, z: 0}\n" +
          hinge);
  return test_support::simulate(
      {model}, [articulation](ambf_like::WorldSpec& world) { world.articulation = articulation; });
}

TEST(CoupledStop, ASumPushedPastItsBoundRestsOnItAndBearsThePush) {
  // Both joints pushed with -0.01 N m toward shoulder + elbow = -0.2 (both start at 0): at rest
  // on the stop, the stop's generalised force along (1, 1) is the 0.01 N m each joint is pushed
  // with, whatever the chain's inertia couples (the sum's acceleration vanishes only then).
  test_support::TempDir dir;
  auto sim = twoLinkChain(dir, ambf_like::Articulation::Reduced);
  ambf_like::World& world = *sim->world;
  const ambf_like::CoupledStop& stop =
      world.addCoupledStop({{"shoulder", "elbow"}, {1.0, 1.0}, -0.2});
  EXPECT_DOUBLE_EQ(stop.gap(), 0.2);
  constexpr double kPush = 0.01;
  for (int k = 0; k < 3000; ++k) {
    world.joint("shoulder").commandEffort(-kPush);
    world.joint("elbow").commandEffort(-kPush);
    world.step(1);
    EXPECT_GT(stop.gap(), -1e-6) << "step " << k;
  }
  const double sum = world.joint("shoulder").position() + world.joint("elbow").position();
  EXPECT_NEAR(sum, -0.2, 1e-6);
  // The sum rests; the chain may still turn along (1, -1), as it did when the sum met the stop.
  EXPECT_LT(std::abs(world.joint("shoulder").velocity() + world.joint("elbow").velocity()), 1e-6);
  EXPECT_NEAR(stop.force(), kPush, 1e-3 * kPush);
}

TEST(CoupledStop, OneThatGivesIsPressedPastItsBoundByTheForceTimesItsCompliance) {
  // A spring where the sum passes its bound: pushed as above from rest on the bound, at rest
  // the sum sits past it by compliance x force, and the force is the push (statics).
  test_support::TempDir dir;
  auto sim = twoLinkChain(dir, ambf_like::Articulation::Reduced);
  ambf_like::World& world = *sim->world;
  ambf_like::CoupledStop& stop = world.addCoupledStop({{"shoulder", "elbow"}, {1.0, 1.0}, 0.0});
  constexpr double kCompliance = 2.0, kPush = 0.01;  // rad per N m, N m
  stop.setCompliance(kCompliance);
  double deepest = 0.0;
  for (int k = 0; k < 6000; ++k) {
    world.joint("shoulder").commandEffort(-kPush);
    world.joint("elbow").commandEffort(-kPush);
    world.step(1);
    deepest = std::min(deepest, stop.gap());
  }
  EXPECT_NEAR(stop.gap(), -kCompliance * kPush, 0.02 * kCompliance * kPush);
  EXPECT_NEAR(stop.force(), kPush, 0.02 * kPush);
  // A step load on an undamped spring goes at most twice as deep as its statics; the implicit
  // solve only loses energy, never gains it.
  EXPECT_GT(deepest, -2.0 * kCompliance * kPush - 1e-6);
  EXPECT_THROW(stop.setCompliance(-1.0), std::invalid_argument);
  EXPECT_THROW(stop.setCompliance(std::nan("")), std::invalid_argument);
}

TEST(CoupledStop, ItNeverPulls) {
  // Both pushed away from the bound (the sum's acceleration is (1, 1) M^-1 (1, 1) times the push,
  // positive), the joints leave it freely: the stop gives nothing.
  test_support::TempDir dir;
  auto sim = twoLinkChain(dir, ambf_like::Articulation::Reduced);
  ambf_like::World& world = *sim->world;
  const ambf_like::CoupledStop& stop =
      world.addCoupledStop({{"shoulder", "elbow"}, {1.0, 1.0}, 0.0});
  for (int k = 0; k < 200; ++k) {
    world.joint("shoulder").commandEffort(0.01);
    world.joint("elbow").commandEffort(0.01);
    world.step(1);
    EXPECT_EQ(stop.force(), 0.0) << "step " << k;
  }
  EXPECT_GT(stop.gap(), 0.01);
}

TEST(CoupledStop, IsRefusedNamingWhatIsWrong) {
  test_support::TempDir dir;
  auto reduced = twoLinkChain(dir, ambf_like::Articulation::Reduced);
  const auto error = [&](ambf_like::World& world, const ambf_like::CoupledStopSpec& spec) {
    try {
      world.addCoupledStop(spec);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    } catch (const std::out_of_range& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  ambf_like::World& world = *reduced->world;
  EXPECT_NE(error(world, {{"shoulder", "elbow"}, {1.0}, 0.0}).find("2 joints and 1 gains"),
            std::string::npos);
  EXPECT_NE(error(world, {{"shoulder", "elbow"}, {1.0, std::nan("")}, 0.0}).find("'elbow'"),
            std::string::npos);
  EXPECT_NE(error(world, {{"shoulder", "elbow"}, {1.0, 1.0}, std::nan("")}).find("lower"),
            std::string::npos);
  EXPECT_NE(error(world, {{"shoulder", "wrist"}, {1.0, 1.0}, 0.0}).find("wrist"),
            std::string::npos);
  auto maximal = twoLinkChain(dir, ambf_like::Articulation::Maximal);
  EXPECT_NE(
      error(*maximal->world, {{"shoulder", "elbow"}, {1.0, 1.0}, 0.0}).find("not a coordinate of"),
      std::string::npos);
}

}  // namespace
