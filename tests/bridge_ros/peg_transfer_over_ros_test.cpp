// The main job over ROS 1, against a real rosmaster: raven_twin_node started in its own process,
// the same scripted operators driving it through RavenRosClient in lock-step and seeing the rings
// on its AMBF object topics; it places all six, and its per-ring table is the in-process run's.

#include "scenario/ros/peg_transfer_over_ros.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "scenario/console_report.hpp"
#include "scenario/peg_transfer.hpp"

namespace {

TEST(PegTransferOverRos, TheDefaultTwinPlacesAllSixAsItDoesInProcess) {
  // The nominal scene on the default (motor) twin, resting rings sleep. Both sides see each
  // ring's pose as a unit quaternion (bridge::asReported): the same commands go into the same
  // physics, and what crosses ROS as float64 (joints, poses) is exact, so the runs are the same
  // (the grasp forces cross as float32).
  scenario::PegTransferOptions options;
  ASSERT_EQ(options.actuation, common::ActuationKind::Motors);
  options.time_limit = 150.0;
  const scenario::PegTransferResult in_process = scenario::runPegTransfer(options);
  const scenario::PegTransferResult over_ros = scenario::ros1::runPegTransferOverRos(options, {});
  std::printf("%s", scenario::ringTable(over_ros).c_str());
  ASSERT_TRUE(in_process.allPlaced()) << in_process.failure;
  ASSERT_TRUE(over_ros.allPlaced()) << over_ros.failure;
  EXPECT_EQ(over_ros.iterations, in_process.iterations);
  EXPECT_NEAR(over_ros.timing.sim_time, in_process.timing.sim_time, 1e-9);
  EXPECT_EQ(over_ros.refused, 0u);
  for (std::size_t i = 0; i < in_process.rings.size(); ++i) {
    const auto& a = over_ros.rings[i];
    const auto& b = in_process.rings[i];
    EXPECT_EQ(a.ring, b.ring);
    EXPECT_EQ(a.grasped, b.grasped) << a.ring;
    EXPECT_EQ(a.placed, b.placed) << a.ring;
    EXPECT_EQ(a.regrasps, b.regrasps) << a.ring;
    EXPECT_FALSE(a.lost) << a.ring << ": " << a.loss;
    EXPECT_LT((a.final_centre - b.final_centre).norm(), 1e-5) << a.ring;
    EXPECT_NEAR(a.lift, b.lift, 1e-5) << a.ring;
    EXPECT_NEAR(a.miss, b.miss, 1e-5) << a.ring;
    for (std::size_t jaw = 0; jaw < 2; ++jaw) {
      EXPECT_NEAR(a.carried_squeeze[jaw], b.carried_squeeze[jaw], 0.01 * b.carried_squeeze[jaw])
          << a.ring;
      // ../shared/reference/soft-materials.md: a few newtons per jaw hold a silicone ring.
      EXPECT_GT(a.carried_squeeze[jaw], 0.5) << a.ring;
      EXPECT_LT(a.carried_squeeze[jaw], 5.0) << a.ring;
    }
    // The in-process world reports the rings' volumes; AMBF's topics do not.
    EXPECT_TRUE(b.volume_seen);
    EXPECT_FALSE(a.volume_seen);
  }
}

TEST(PegTransferOverRos, TheNodeRunsOnTheCalibrationTheRunWasGiven) {
  scenario::PegTransferOptions options;
  const auto flag = [](const std::vector<std::string>& argv) {
    const auto at = std::find(argv.begin(), argv.end(), "--calibration");
    return at == argv.end() || at + 1 == argv.end() ? std::string() : *(at + 1);
  };
  EXPECT_EQ(flag(scenario::ros1::twinNodeCommand("node", "/ns", options)), "")
      << "the shipped profile: the node's own default";
  options.calibration = "/profiles/fitted.yaml";
  EXPECT_EQ(flag(scenario::ros1::twinNodeCommand("node", "/ns", options)), "/profiles/fitted.yaml");
}

TEST(PegTransferOverRos, RefusesWhatOnlyAnInProcessWorldCanDo) {
  scenario::PegTransferOptions randomized;
  randomized.randomize = true;
  EXPECT_THROW(scenario::ros1::runPegTransferOverRos(randomized, {}), std::invalid_argument);
  scenario::PegTransferOptions assisted;
  assisted.assist = scenario::AssistMode::Contact;
  EXPECT_THROW(scenario::ros1::runPegTransferOverRos(assisted, {}), std::invalid_argument);
}

}  // namespace
