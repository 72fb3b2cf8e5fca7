// The checks a peg-transfer run is judged by, on the real scene and through the perception a run
// sees it by: a ring's pose (its nodes' shape-matched frame) gives its extremes and whether a
// post passes through its hole; a ring counts as placed only when threaded on its post and down
// on the board; RingWatch calls a ring lost when its pose goes non-finite, its volume leaves the
// 20 % band, or it falls through the board.

#include <BulletSoftBody/btSoftBody.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <regex>
#include <sstream>

#include "scenario/peg_layout.hpp"
#include "scenario/ring_nodes.hpp"
#include "scenario/ring_watch.hpp"
#include "twin/twin_platform.hpp"
#include "twin/world_perception.hpp"

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

/// Turns every node by `turn` about the nodes' mean.
void rotate(btSoftBody& body, const Eigen::Matrix3d& turn) {
  btVector3 mean(0, 0, 0);
  for (int i = 0; i < body.m_nodes.size(); ++i) mean += body.m_nodes[i].m_x;
  mean /= body.m_nodes.size();
  for (int i = 0; i < body.m_nodes.size(); ++i) {
    const btVector3 d = body.m_nodes[i].m_x - mean;
    const Eigen::Vector3d r = turn * Eigen::Vector3d(d.x(), d.y(), d.z());
    body.m_nodes[i].m_x = mean + btVector3(r.x(), r.y(), r.z());
  }
}

scenario::RingView seen(const twin::WorldPerception& scene, const std::string& ring) {
  return scenario::RingView(scene.sight(ring), PegLayout{}.ring);
}

TEST(PegChecks, EveryRingIsThreadedOnItsStartPostAndOnNoOther) {
  twin::TwinPlatform twin(pegScene());
  const twin::WorldPerception scene(twin.world());
  const PegLayout layout = PegLayout::seen(scene);
  for (const auto& job : layout.jobs) {
    const auto ring = seen(scene, job.ring);
    EXPECT_TRUE(scenario::restsOn(ring, job.from, layout.geometry)) << job.ring;
    EXPECT_FALSE(scenario::restsOn(ring, job.to, layout.geometry)) << job.ring;
    EXPECT_LT(ring.postOffset(job.from), 1e-9) << job.ring;  // made centred on it
  }
}

TEST(PegChecks, TheBoardSeenPlacesThePostsOfTheDesign) {
  twin::TwinPlatform twin(pegScene());
  const PegLayout seen_layout = PegLayout::seen(twin::WorldPerception(twin.world()));
  const PegLayout design;
  for (std::size_t i = 0; i < design.jobs.size(); ++i) {
    EXPECT_LT((seen_layout.jobs[i].from - design.jobs[i].from).norm(), 1e-12);
    EXPECT_LT((seen_layout.jobs[i].to - design.jobs[i].to).norm(), 1e-12);
  }
  EXPECT_DOUBLE_EQ(seen_layout.geometry.board_top, design.geometry.board_top);
  // A board seen turned by 90 degrees about its centre carries its posts with it.
  Eigen::Isometry3d turned = Eigen::Isometry3d::Identity();
  turned.translation() << 0.0, 0.08, design.geometry.board_top;
  turned.linear() = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const PegLayout moved(raven::design::PegSceneDesign{}, turned);
  const Eigen::Vector2d local = design.jobs[0].from - Eigen::Vector2d(0.0, 0.08);
  EXPECT_LT(
      (moved.jobs[0].from - (Eigen::Vector2d(-local.y(), local.x()) + Eigen::Vector2d(0.0, 0.08)))
          .norm(),
      1e-12);
}

TEST(PegChecks, AnOldSceneWhoseRingsAreCalledPegsIsSeenByItsOwnNames) {
  namespace fs = std::filesystem;
  const fs::path shipped = raven::modelDirectory() / "peg_transfer";
  const fs::path dir = fs::path(::testing::TempDir()) / "legacy_ring_names";
  fs::create_directories(dir);
  std::ifstream rings(shipped / "rings.yaml");
  std::stringstream text;
  text << rings.rdbuf();
  std::string legacy = std::regex_replace(text.str(), std::regex("ring([1-6])"), "peg$1");
  legacy = std::regex_replace(legacy, std::regex("\\./meshes/"), (shipped / "meshes/").string());
  std::ofstream(dir / "pegs.yaml") << legacy;
  std::ofstream(dir / "launch.yaml")
      << "world config: " << (shipped / "world.yaml").string() << "\nmultibody configs:\n"
      << "  - " << (shipped / "../raven2/raven2_left.yaml").string() << "\n"
      << "  - " << (shipped / "../raven2/raven2_right.yaml").string() << "\n"
      << "  - " << (shipped / "peg_board.yaml").string() << "\n  - pegs.yaml\n";
  twin::TwinOptions options;
  options.launch_file = dir / "launch.yaml";
  twin::TwinPlatform old_scene(options);
  const PegLayout layout = PegLayout::seen(twin::WorldPerception(old_scene.world()));
  for (std::size_t i = 0; i < layout.jobs.size(); ++i) {
    EXPECT_EQ(layout.jobs[i].ring, "peg" + std::to_string(i + 1));
    EXPECT_EQ(scenario::ringIndexOf(layout.jobs[i].ring), i);
  }
  twin::TwinPlatform today(pegScene());
  EXPECT_EQ(PegLayout::seen(twin::WorldPerception(today.world())).jobs[5].ring, "ring6");
  EXPECT_EQ(scenario::ringIndexOf("ring6"), 5u);
  EXPECT_FALSE(scenario::ringIndexOf("ring7"));
  EXPECT_FALSE(scenario::ringIndexOf(PegLayout::kBoard));
}

TEST(PegChecks, ARingsPoseFollowsItsNodesAndGivesTheirExtremes) {
  twin::TwinPlatform twin(pegScene());
  auto& world = twin.world();
  const twin::WorldPerception scene(world);
  const auto& body = world.softBody("ring1");
  // At rest: the spec's orientation, at the nodes' mean, the extremes the nodes have.
  auto nodeExtremes = [&] {
    const auto s = scenario::inspect(body);
    double top = -1.0;
    for (const auto& p : body.nodePositions()) top = std::max(top, p.z());
    return std::pair{s.bottom, top};
  };
  auto ring = seen(scene, "ring1");
  EXPECT_TRUE(ring.pose.linear().isApprox(body.spec().location.linear(), 1e-9));
  EXPECT_LT((ring.centre() - scenario::inspect(body).centre).norm(), 1e-12);
  EXPECT_NEAR(ring.bottom(), nodeExtremes().first, 1e-9);
  EXPECT_NEAR(ring.top(), nodeExtremes().second, 1e-9);
  // Tipped by 0.4 rad about x and turned about z: the pose turns with it, and the extremes are
  // the elliptic tube's, which the octagonal mesh inscribes (within a few tenths of a mm).
  const Eigen::Matrix3d turn = (Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()) *
                                Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitX()))
                                   .toRotationMatrix();
  rotate(world.softBody("ring1").bullet(), turn);
  ring = seen(scene, "ring1");
  EXPECT_TRUE(ring.pose.linear().isApprox(turn * body.spec().location.linear(), 1e-9));
  EXPECT_LE(ring.bottom(), nodeExtremes().first + 1e-9);
  EXPECT_GT(ring.bottom(), nodeExtremes().first - 0.0005);
  EXPECT_GE(ring.top(), nodeExtremes().second - 1e-9);
  EXPECT_LT(ring.top(), nodeExtremes().second + 0.0005);
}

TEST(PegChecks, TheStationTowardASideIsTheRingsNearestStationNode) {
  // The mesh (raven_description's solidRing): per station its centre-line node, then 8 around
  // the tube; station i at 2 pi i / 16 about the ring's axis. -y is station 12's side.
  twin::TwinPlatform twin(pegScene());
  auto& world = twin.world();
  const twin::WorldPerception scene(world);
  const auto& body = world.softBody("ring1");
  const std::size_t per_station = 9;
  const Eigen::Vector2d minus_y(0, -1);
  EXPECT_LT(
      (seen(scene, "ring1").stationToward(minus_y) - body.nodePosition(12 * per_station)).norm(),
      1e-9);
  // Turned by 0.3 rad (more than half a station, 0.196 rad): station 11 faces -y now.
  rotate(world.softBody("ring1").bullet(),
         Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()).toRotationMatrix());
  EXPECT_LT(
      (seen(scene, "ring1").stationToward(minus_y) - body.nodePosition(11 * per_station)).norm(),
      1e-9);
}

TEST(PegChecks, ARingPerchedAboveItsPostOrBesideItIsNotPlaced) {
  twin::TwinPlatform twin(pegScene());
  const twin::WorldPerception scene(twin.world());
  const PegLayout layout;
  const auto& job = layout.jobs[0];
  auto& peg = twin.world().softBody(job.ring);
  translate(peg.bullet(), btVector3(0, 0, 0.03));  // held over the post, not on it
  EXPECT_TRUE(seen(scene, job.ring).threadedOn(job.from));
  EXPECT_FALSE(scenario::restsOn(seen(scene, job.ring), job.from, layout.geometry));
  translate(peg.bullet(), btVector3(0.012, 0, -0.03));  // down on the board, beside the post
  EXPECT_FALSE(seen(scene, job.ring).threadedOn(job.from));
  EXPECT_FALSE(scenario::restsOn(seen(scene, job.ring), job.from, layout.geometry));
  // Leaning on the post (its hole's edge 1 mm from the post's axis) it is still threaded.
  translate(peg.bullet(), btVector3(-0.012 + layout.ring.innerRadius() - 0.001, 0, 0));
  EXPECT_TRUE(scenario::restsOn(seen(scene, job.ring), job.from, layout.geometry));
}

TEST(PegChecks, TheVolumeFromTheNodesIsTheRingsPolyhedralVolume) {
  twin::TwinPlatform twin(pegScene());
  const PegLayout layout;
  // An octagon inscribed in the 2 x 5 mm elliptical section (area 2 sqrt(2) a b) lofted in 16
  // straight segments around the 8 mm radius: each segment holds A R 2 sin(pi/16) cos(pi/16).
  const double section = 2 * std::sqrt(2.0) * layout.ring.tube_half_width * layout.ring.half_height;
  const double perimeter = 16 * layout.ring.major_radius * std::sin(2 * M_PI / 16);
  for (const auto& job : layout.jobs) {
    const auto& ring = twin.world().softBody(job.ring);
    EXPECT_NEAR(ring.volume(), section * perimeter, 1e-6 * section * perimeter) << job.ring;
    EXPECT_DOUBLE_EQ(ring.restVolume(), ring.volume()) << job.ring;
  }
}

TEST(RingWatch, CallsARingLostForEachKindOfLoss) {
  twin::TwinPlatform twin(pegScene());
  auto& world = twin.world();
  const twin::WorldPerception scene(world);
  scenario::RingWatch watch(PegLayout{});
  watch.observe(scene);
  EXPECT_EQ(watch.lost(), 0u);

  world.softBody("ring1").bullet().m_nodes[5].m_x.setX(std::numeric_limits<double>::quiet_NaN());
  btSoftBody& swollen = world.softBody("ring2").bullet();  // 1.1^3 = 1.33 times its volume
  const btVector3 centre = swollen.m_nodes[0].m_x;
  for (int i = 0; i < swollen.m_nodes.size(); ++i) {
    swollen.m_nodes[i].m_x = centre + (swollen.m_nodes[i].m_x - centre) * 1.1;
  }
  translate(world.softBody("ring4").bullet(), btVector3(0, 0, -0.01));  // under the board
  watch.observe(scene);

  const auto outcomes = watch.finish(scene);
  EXPECT_EQ(watch.lost(), 3u);
  EXPECT_EQ(outcomes[0].loss, "non-finite pose");
  EXPECT_NE(outcomes[1].loss.find("volume"), std::string::npos) << outcomes[1].loss;
  EXPECT_EQ(outcomes[3].loss, "fell through the board");
  for (std::size_t i : {0u, 1u, 3u}) EXPECT_FALSE(outcomes[i].placed) << outcomes[i].ring;
  EXPECT_FALSE(outcomes[2].lost);
}

}  // namespace
