// The main job's batches: the nominal scene on the default (motor-level) twin, and 20 seeded
// randomised peg transfers on ideal servos and on the motor twin (start poses, friction,
// softness, the motors' mechanics drawn from each seed), the rings held by contact and friction
// alone, on two worker threads and the simulated clock. At least 19 must place all six rings; no
// peg may ever be lost, crushed (volume within 20 % of rest) or pushed through the board. The grasp
// assist's 20 as well.

#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <sys/inotify.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "harness/child_process.hpp"
#include "harness/temp_dir.hpp"
#include "scenario/batch.hpp"
#include "scenario/console_report.hpp"
#include "scenario/peg_transfer.hpp"

namespace {

TEST(PegTransferBatch, TheNominalSceneIsPlacedWholeByFrictionAlone) {
  const auto result = scenario::runPegTransfer({});
  EXPECT_TRUE(result.allPlaced());
  EXPECT_FALSE(result.timed_out);
  std::printf("%s", scenario::ringTable(result).c_str());
  for (const auto& p : result.rings) {
    EXPECT_TRUE(p.placed) << p.ring << " " << p.miss * 1e3 << " mm off";
    EXPECT_FALSE(p.lost) << p.ring << ": " << p.loss;
    EXPECT_GT(p.min_volume_ratio, 0.8);
  }
}

/// Seeds 1-20 of `options` randomised on two threads: at least 19 runs place all six, none times
/// out or has a command refused, no ring is lost or crushed.
void expectNineteenOfTwentyPlaceAllSix(scenario::PegTransferOptions options) {
  options.randomize = true;
  ASSERT_EQ(options.assist, scenario::AssistMode::Off);
  const auto seeds = scenario::seedsOf(1, 20, scenario::Shard{});
  const auto results = scenario::runBatch(options, seeds, 2);

  ASSERT_EQ(results.size(), 20u);
  std::printf("%s", scenario::batchTable(results).c_str());
  std::size_t complete = 0;
  for (const auto& r : results) {
    complete += r.allPlaced() ? 1 : 0;
    EXPECT_FALSE(r.timed_out) << "seed " << r.variation.seed;
    EXPECT_EQ(r.refused, 0u) << "seed " << r.variation.seed;
    for (const auto& p : r.rings) {
      EXPECT_FALSE(p.lost) << "seed " << r.variation.seed << " " << p.ring << ": " << p.loss;
      EXPECT_GT(p.min_volume_ratio, 0.8);
      EXPECT_LT(p.max_volume_ratio, 1.2);
      if (!p.placed) {
        std::printf("seed %llu: %s not placed (%.1f mm from its post's axis)\n",
                    static_cast<unsigned long long>(r.variation.seed), p.ring.c_str(),
                    p.miss * 1e3);
      }
    }
  }
  EXPECT_GE(complete, 19u);
}

TEST(PegTransferBatch, OnIdealServosNineteenOfTwentyRandomisedRunsPlaceAllSixAndNoneIsLost) {
  // The operator and the friction grasp alone, on joints that go where they are told.
  scenario::PegTransferOptions options;
  options.actuation = common::ActuationKind::Ideal;
  expectNineteenOfTwentyPlaceAllSix(options);
}

TEST(PegTransferBatch, OnTheMotorTwinNineteenOfTwentyRandomisedRunsPlaceAllSixAndNoneIsLost) {
  // The default twin: the Raven-II's motors drive the joints, each motor's fitted mechanics
  // drawn within the calibration's deviations (issue 64's bar for the main job).
  scenario::PegTransferOptions options;
  ASSERT_EQ(options.actuation, common::ActuationKind::Motors);
  expectNineteenOfTwentyPlaceAllSix(options);
}

/// Every peg of `r` placed, whole: finite, its volume within 0.5-2 of its rest volume.
void expectAllPlacedWhole(const scenario::PegTransferResult& r) {
  EXPECT_EQ(r.failure, "") << "seed " << r.variation.seed;
  EXPECT_TRUE(r.allPlaced()) << "seed " << r.variation.seed;
  for (const auto& p : r.rings) {
    EXPECT_FALSE(p.lost) << "seed " << r.variation.seed << " " << p.ring << ": " << p.loss;
    EXPECT_GT(p.min_volume_ratio, 0.5) << "seed " << r.variation.seed << " " << p.ring;
    EXPECT_LT(p.max_volume_ratio, 2.0) << "seed " << r.variation.seed << " " << p.ring;
  }
}

TEST(PegTransferBatch, TheGraspAssistPinsEveryRingWholeOnTheNominalAndTwentyRandomisedScenes) {
  // The anchors are pins inside the rings' implicit solve: Bullet's own anchor pass after it
  // crushed two rings of the nominal scene to a volume ratio of 1e32 (issue 45).
  scenario::PegTransferOptions options;
  options.actuation = common::ActuationKind::Ideal;  // the assist's own checks, as its pins are
  options.assist = scenario::AssistMode::Contact;
  const auto nominal = scenario::runPegTransfer(options);
  std::printf("%s", scenario::ringTable(nominal).c_str());
  expectAllPlacedWhole(nominal);
  options.randomize = true;
  const auto results = scenario::runBatch(options, scenario::seedsOf(1, 20, scenario::Shard{}), 2);
  ASSERT_EQ(results.size(), 20u);
  std::printf("%s", scenario::batchTable(results).c_str());
  for (const auto& r : results) expectAllPlacedWhole(r);
}

TEST(PegTransferBatch, AnOperatorWhoseGripCannotHoldTriesEachRingThreeTimesAndMovesOn) {
  // Closed to 0.3 mm short of the wall no ring is carried: the operator sees it each time, opens,
  // grasps again, twice per peg, and then leaves it where it is. (Rings knocked about by three
  // grasps that cannot hold them may end anywhere, through the board included: that is not
  // asserted.)
  // On ideal servos: the motors' closing jaws overshoot their command and may pinch a ring even
  // so, which is not the operator's rule this checks.
  scenario::PegTransferOptions options;
  options.actuation = common::ActuationKind::Ideal;
  options.squeeze = -0.0003;
  const auto result = scenario::runPegTransfer(options);
  std::printf("%s", scenario::ringTable(result).c_str());
  EXPECT_FALSE(result.timed_out);
  EXPECT_EQ(result.placed(), 0u);
  EXPECT_EQ(result.regrasps(), 12u);
  for (const auto& p : result.rings) EXPECT_EQ(p.regrasps, 2) << p.ring;
  EXPECT_EQ(result.json()["regrasps"], 12);
}

TEST(PegTransferBatch, AStoppedBatchKeepsWhatFinishedAndARecordedOneWritesEveryRunsFile) {
  harness::TempDir dir;
  std::atomic<bool> stop{false};
  scenario::PegTransferOptions options;
  options.randomize = true;
  options.rs_folder = dir.path();
  options.stop = &stop;
  // One worker: the first run finishes, asks the batch to stop (as SIGTERM's handler would),
  // and the second and third never start.
  const auto results = scenario::runBatch(options, {5, 6, 7}, 1, [&](const auto&) { stop = true; });
  ASSERT_EQ(results.size(), 1u);
  EXPECT_EQ(results[0].variation.seed, 5u);
  EXPECT_FALSE(results[0].stopped);
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "peg_transfer_seed5_rs.csv"));
  EXPECT_GT(results[0].rs_rows, 100u);
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "peg_transfer_seed6_rs.csv"));
  // A run asked to stop while it runs ends at once and says so.
  const auto cut = scenario::runBatch(options, {8}, 1);
  ASSERT_EQ(cut.size(), 0u) << "asked to stop before it started: not run";
  stop = false;
  options.progress = [&](const scenario::RunProgress&) { stop = true; };
  const auto stopped = scenario::runPegTransfer(options);
  EXPECT_TRUE(stopped.stopped);
  EXPECT_FALSE(stopped.timed_out);
  EXPECT_EQ(stopped.iterations, 1u) << "it ends after the iteration it was asked in";
}

TEST(PegTransferBatch, SigtermStopsTheProgramsBatchAndItWritesWhatFinished) {
  harness::TempDir dir;
  harness::ChildProcess program({RAVEN_PEG_TRANSFER, "--runs", "3", "--threads", "1", "--randomize",
                                 "--out", dir.path().string(), "-q"},
                                dir.path() / "log.txt");
  // SIGTERM as soon as the first run is on disk: a line in runs.jsonl (woken by inotify).
  const auto jsonl = dir.path() / "runs.jsonl";
  const int watch = inotify_init1(IN_NONBLOCK);
  ASSERT_GE(watch, 0);
  ASSERT_GE(inotify_add_watch(watch, dir.path().c_str(), IN_MODIFY | IN_CREATE), 0);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(5);
  while (!std::filesystem::exists(jsonl) || std::filesystem::file_size(jsonl) == 0) {
    ASSERT_LT(std::chrono::steady_clock::now(), deadline) << "no run finished";
    ASSERT_EQ(::kill(program.pid(), 0), 0) << "the program ended before its first run did";
    pollfd event{watch, POLLIN, 0};
    if (poll(&event, 1, 1000) > 0) {
      char drained[4096];
      while (read(watch, drained, sizeof drained) > 0) {
      }
    }
  }
  close(watch);
  ASSERT_EQ(::kill(program.pid(), SIGTERM), 0);
  EXPECT_EQ(program.wait(60.0), 130) << "a stopped batch exits 130, within one iteration";
  std::ifstream summary_file(dir.path() / "summary.json");
  ASSERT_TRUE(summary_file) << "no summary.json";
  const auto summary = nlohmann::json::parse(summary_file);
  EXPECT_TRUE(summary["stopped"].get<bool>());
  EXPECT_EQ(summary["runs_asked"], 3);
  EXPECT_GE(summary["results"].size(), 1u);
  EXPECT_LT(summary["results"].size(), 3u) << "the third run should never have started";
}

}  // namespace
