// Splitting a batch: --shard parsing with clear errors, and shards that together hold every run
// exactly once; the handover verdict; the run's JSON line.

#include "scenario/batch.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "raven/platform_profile.hpp"
#include "scenario/batch_summary.hpp"
#include "scenario/console_report.hpp"
#include "scenario/handover_reach.hpp"

namespace {

using scenario::Shard;

TEST(Shard, ParsesOneBasedIndexOverCount) {
  const Shard s = Shard::parse("3/8");
  EXPECT_EQ(s.index, 3u);
  EXPECT_EQ(s.count, 8u);
  EXPECT_EQ(Shard::parse("1/1").count, 1u);
}

TEST(Shard, RefusesMalformedTextQuotingIt) {
  for (const char* bad : {"", "3", "0/4", "5/4", "1/0", "a/b", "2/4x", "-1/4", "2//4", " 1/2"}) {
    try {
      Shard::parse(bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(std::string("'") + bad + "'"), std::string::npos)
          << e.what();
    }
  }
}

TEST(Shard, TheShardsOfABatchHoldEveryRunExactlyOnce) {
  for (std::size_t count : {1u, 2u, 3u, 7u, 25u}) {
    std::multiset<std::uint64_t> all;
    for (std::size_t i = 1; i <= count; ++i) {
      const auto seeds = scenario::seedsOf(100, 20, Shard{i, count});
      EXPECT_TRUE(std::is_sorted(seeds.begin(), seeds.end()));
      all.insert(seeds.begin(), seeds.end());
    }
    ASSERT_EQ(all.size(), 20u) << count << " shards";
    for (std::uint64_t seed = 100; seed < 120; ++seed) EXPECT_EQ(all.count(seed), 1u) << seed;
  }
}

TEST(Handover, TheArmsWorkspacesNeverMeetWithTheseBaseFrames) {
  const auto reach = scenario::measureHandoverReach(raven::builtinProfile("physical"), 20000);
  EXPECT_EQ(reach.samples_per_arm, 20000u);
  EXPECT_GT(reach.left_min_x, 0.15);
  EXPECT_LT(reach.right_max_x, -0.15);
  EXPECT_GT(reach.gap(), 0.3);
  EXPECT_FALSE(reach.possible(0.0102));
  EXPECT_NE(reach.explain(0.0102).find("impossible"), std::string::npos);
  // The verdict follows the numbers: workspaces that overlap would allow it.
  scenario::HandoverReach overlapping{1, -0.01, 0.01};
  EXPECT_TRUE(overlapping.possible(0.0102));
}

TEST(BatchSummary, CountsRunsPegsAndRates) {
  std::vector<scenario::PegTransferResult> results(2);
  for (auto& p : results[0].rings) p.placed = true;
  results[1].rings[0].placed = true;
  results[1].rings[1].lost = true;
  results[0].timing = {10.0, 6.0, 5.0, 10000};
  results[1].timing = {20.0, 11.0, 10.0, 20000};
  const auto j = scenario::summarize(results);
  EXPECT_EQ(j["runs"], 2);
  EXPECT_EQ(j["runs_all_placed"], 1);
  EXPECT_EQ(j["rings_placed"], 7);
  EXPECT_EQ(j["rings_lost"], 1);
  EXPECT_DOUBLE_EQ(j["real_time_factor"].get<double>(), 2.0);
  EXPECT_DOUBLE_EQ(j["loop_frequency_hz"].get<double>(), 2000.0);
}

TEST(BatchSummary, TotalsAddUpOneRunAtATime) {
  // A batch keeps only the running totals while it runs (constant memory); after every run they
  // are what the rows so far sum to.
  std::vector<scenario::PegTransferResult> results(3);
  for (auto& p : results[0].rings) p.placed = true;
  results[1].rings[3].lost = true;
  results[2].failure = "the simulation diverged";
  results[2].timed_out = true;
  for (std::size_t i = 0; i < results.size(); ++i) {
    results[i].timing = {5.0 * (i + 1), 2.0 + i, 1.5 + i, 5000 * (i + 1)};
  }
  scenario::RunTotals totals;
  const std::array<int, 3> placed{6, 6, 6}, lost{0, 1, 1}, failed{0, 0, 1}, timed_out{0, 0, 1};
  const std::array<double, 3> simulated{5.0, 15.0, 30.0};
  for (std::size_t i = 0; i < results.size(); ++i) {
    totals.add(results[i].json());
    const nlohmann::json j = totals.json();
    EXPECT_EQ(j["runs"], i + 1);
    EXPECT_EQ(j["runs_all_placed"], 1);
    EXPECT_EQ(j["rings_placed"], placed[i]);
    EXPECT_EQ(j["rings_lost"], lost[i]);
    EXPECT_EQ(j["runs_failed"], failed[i]);
    EXPECT_EQ(j["runs_timed_out"], timed_out[i]);
    EXPECT_DOUBLE_EQ(j["sim_time_s"].get<double>(), simulated[i]);
  }
}

TEST(BatchSummary, ARunWhoseWorldBlewUpIsCountedFailedAndPrintsNoPegNumbers) {
  std::vector<scenario::PegTransferResult> results(2);
  for (auto& p : results[0].rings) p.placed = true;
  results[1].failure = "the simulation diverged at step 5 (t = 0.0050 s): soft body 'ring3' node 2";
  results[1].rings[2].min_volume_ratio = 1e32;  // what a blown-up ring would show
  results[1].variation.seed = 7;
  const auto row = results[1].json();
  EXPECT_EQ(row["failure"], results[1].failure);
  EXPECT_TRUE(row["rings"].empty()) << "no peg numbers from a world that blew up";
  EXPECT_FALSE(row["all_placed"]);
  EXPECT_TRUE(results[0].json()["failure"].is_null());
  EXPECT_EQ(scenario::ringTable(results[1]), "the run failed: " + results[1].failure + "\n");
  const std::string table = scenario::batchTable(results);
  EXPECT_NE(table.find("     7 failed: the simulation diverged"), std::string::npos) << table;
  EXPECT_EQ(table.find("1e+32"), std::string::npos) << table;
  const auto j = scenario::summarize(results);
  EXPECT_EQ(j["runs_failed"], 1);
  EXPECT_EQ(j["runs_all_placed"], 1);
}

}  // namespace
