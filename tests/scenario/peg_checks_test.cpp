// The checks a peg-transfer run is judged by, on the real scene: a ring counts as placed only
// when threaded on its post and down on the board, and PegWatch calls a peg lost when its nodes
// go non-finite, its volume leaves the 20 % band, or it falls through the board.

#include <BulletSoftBody/btSoftBody.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "scenario/peg_layout.hpp"
#include "scenario/peg_state.hpp"
#include "scenario/peg_watch.hpp"
#include "twin/twin_platform.hpp"

namespace {

using scenario::PegLayout;

twin::TwinOptions pegScene() {
  twin::TwinOptions options;
  options.launch_file = raven::modelDirectory() / "peg_transfer" / "launch.yaml";
  return options;
}

void translate(btSoftBody& body, const btVector3& by) {
  for (int i = 0; i < body.m_nodes.size(); ++i) body.m_nodes[i].m_x += by;
}

TEST(PegChecks, EveryRingIsThreadedOnItsStartPostAndOnNoOther) {
  twin::TwinPlatform twin(pegScene());
  const PegLayout layout;
  for (const auto& job : layout.jobs) {
    const auto& peg = twin.world().softBody(job.peg);
    EXPECT_TRUE(scenario::restsOn(peg, job.from, layout.geometry)) << job.peg;
    EXPECT_FALSE(scenario::restsOn(peg, job.to, layout.geometry)) << job.peg;
    EXPECT_LT(scenario::bearingGap(peg, job.from), 2 * M_PI / 16 + 0.01) << job.peg;  // 16 stations
    EXPECT_GT(scenario::bearingGap(peg, job.to), M_PI) << job.peg;  // all on one side
  }
}

TEST(PegChecks, ARingPerchedAboveItsPostOrBesideItIsNotPlaced) {
  twin::TwinPlatform twin(pegScene());
  const PegLayout layout;
  const auto& job = layout.jobs[0];
  auto& peg = twin.world().softBody(job.peg);
  translate(peg.bullet(), btVector3(0, 0, 0.03));  // held over the post, not on it
  EXPECT_FALSE(scenario::restsOn(peg, job.from, layout.geometry));
  translate(peg.bullet(), btVector3(0.012, 0, -0.03));  // down on the board, beside the post
  EXPECT_FALSE(scenario::restsOn(peg, job.from, layout.geometry));
  EXPECT_GT(scenario::bearingGap(peg, job.from), M_PI);
}

TEST(PegChecks, TheVolumeFromTheNodesIsTheRingsPolyhedralVolume) {
  twin::TwinPlatform twin(pegScene());
  const PegLayout layout;
  // An octagon inscribed in the 2 x 5 mm elliptical section (area 2 sqrt(2) a b) lofted in 16
  // straight segments around the 8 mm radius: each segment holds A R 2 sin(pi/16) cos(pi/16).
  const double section = 2 * std::sqrt(2.0) * layout.tube_half_width * (layout.ring_height / 2);
  const double perimeter = 16 * layout.ring_radius * std::sin(2 * M_PI / 16);
  for (const auto& job : layout.jobs) {
    EXPECT_NEAR(scenario::inspect(twin.world().softBody(job.peg)).volume, section * perimeter,
                1e-6 * section * perimeter)
        << job.peg;
  }
}

TEST(PegWatch, CallsAPegLostForEachKindOfLoss) {
  twin::TwinPlatform twin(pegScene());
  auto& world = twin.world();
  scenario::PegWatch watch(world, PegLayout{});
  watch.observe();
  EXPECT_EQ(watch.lost(), 0u);

  world.softBody("peg1").bullet().m_nodes[5].m_x.setX(std::numeric_limits<double>::quiet_NaN());
  btSoftBody& swollen = world.softBody("peg2").bullet();  // 1.1^3 = 1.33 times its volume
  const btVector3 centre = swollen.m_nodes[0].m_x;
  for (int i = 0; i < swollen.m_nodes.size(); ++i) {
    swollen.m_nodes[i].m_x = centre + (swollen.m_nodes[i].m_x - centre) * 1.1;
  }
  translate(world.softBody("peg4").bullet(), btVector3(0, 0, -0.01));  // under the board
  watch.observe();

  const auto outcomes = watch.finish();
  EXPECT_EQ(watch.lost(), 3u);
  EXPECT_EQ(outcomes[0].loss, "non-finite node positions");
  EXPECT_NE(outcomes[1].loss.find("volume"), std::string::npos) << outcomes[1].loss;
  EXPECT_EQ(outcomes[3].loss, "fell through the board");
  for (std::size_t i : {0u, 1u, 3u}) EXPECT_FALSE(outcomes[i].placed) << outcomes[i].peg;
  EXPECT_FALSE(outcomes[2].lost);
}

}  // namespace
