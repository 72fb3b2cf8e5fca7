// A sharded batch's plan and merge: the options a plan refuses, a folder holding another batch,
// and a merge that finds every seed once or names what is missing, twice, cut short or foreign.

#include "scenario/batch_merge.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "scenario/batch_summary.hpp"
#include "test_files.hpp"

namespace {

using scenario::BatchPlan;

/// Seeds 10..15 in two shards: shard 1 runs 10, 12, 14 and shard 2 runs 11, 13, 15.
BatchPlan sixRunsInTwoShards() {
  return {10, 6, 2, {"--randomize", "--squeeze", "1.0"}};
}

scenario::PegTransferResult runOf(std::uint64_t seed, std::size_t placed, bool stopped = false) {
  scenario::PegTransferResult r;
  r.variation.seed = seed;
  for (std::size_t i = 0; i < placed; ++i) r.rings[i].placed = true;
  r.stopped = stopped;
  r.timing = {60.0 + static_cast<double>(seed), 9.0, 8.0, 60000 + seed};
  return r;
}

std::string linesOf(const std::vector<scenario::PegTransferResult>& runs) {
  std::string text;
  for (const auto& r : runs) text += r.json().dump() + '\n';
  return text;
}

bool mentions(const std::vector<std::string>& problems, const std::string& text) {
  return std::any_of(problems.begin(), problems.end(),
                     [&](const std::string& p) { return p.find(text) != std::string::npos; });
}

TEST(BatchPlan, RefusesOptionsThePlanSetsOrABatchCannotTakeByName) {
  BatchPlan plan = sixRunsInTwoShards();
  EXPECT_NO_THROW(plan.validate());
  for (const char* option :
       {"--seed=3", "--shard", "--out", "--runs", "--jsonl", "--task", "--gui", "--snapshot"}) {
    plan.options = {option};
    try {
      plan.validate();
      ADD_FAILURE() << option << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(std::string(option).substr(0, 6)), std::string::npos)
          << e.what();
    }
  }
  EXPECT_THROW((BatchPlan{0, 4, 5, {}}.validate()), std::invalid_argument);  // shards > runs
  EXPECT_THROW((BatchPlan{0, 0, 1, {}}.validate()), std::invalid_argument);
}

TEST(BatchPlan, ShardArgumentsAddSeedRunsShardAndFolderToThePlansOptions) {
  const auto args = sixRunsInTwoShards().shardArguments(2, "/shared/batch");
  const std::vector<std::string> expected{"--seed",      "10",        "--runs", "6",
                                          "--shard",     "2/2",       "--out",  "/shared/batch",
                                          "--randomize", "--squeeze", "1.0"};
  EXPECT_EQ(args, expected);
}

TEST(BatchPlan, AFolderKeepsOnePlanAndReadsItBack) {
  harness::TempDir dir;
  const BatchPlan plan = sixRunsInTwoShards();
  plan.write(dir.path());
  EXPECT_NO_THROW(plan.write(dir.path()));  // the same plan again: a resubmission
  EXPECT_EQ(BatchPlan::read(dir.path()), plan);
  BatchPlan other = plan;
  other.first_seed = 11;
  EXPECT_THROW(other.write(dir.path()), std::runtime_error);
}

TEST(BatchPlan, AMissingOrMalformedPlanIsAnErrorNamingFileAndField) {
  harness::TempDir dir;
  try {
    BatchPlan::read(dir.path());
    ADD_FAILURE() << "no plan read";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("batch.json: no batch plan"), std::string::npos);
  }
  dir.write("batch.json", R"({"first_seed": 1, "runs": 8, "options": []})");
  try {
    BatchPlan::read(dir.path());
    ADD_FAILURE() << "a plan without shards read";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("'shards'"), std::string::npos) << e.what();
  }
  // Counts are whole numbers within reach: 1e300 runs had merge and run allocating until memory
  // ran out, and nlohmann reads 1e300 and -5 as counts without a word.
  for (const auto& [plan, wanted] : std::vector<std::pair<std::string, std::string>>{
           {R"({"first_seed": 0, "runs": 1e300, "shards": 2, "options": []})",
            "runs: 1e+300 is not a whole number >= 0"},
           {R"({"first_seed": -5, "runs": 8, "shards": 2, "options": []})",
            "first_seed: -5 is not a whole number >= 0"},
           {R"({"first_seed": 0, "runs": 1000001, "shards": 2, "options": []})",
            "runs: 1000001 (a batch holds at most 1000000)"},
           {R"({"first_seed": 18446744073709551615, "runs": 2, "shards": 2, "options": []})",
            "first_seed: 18446744073709551615 leaves no room for 2 seeds"}}) {
    dir.write("batch.json", plan);
    try {
      BatchPlan::read(dir.path());
      ADD_FAILURE() << plan << " read";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(wanted), std::string::npos) << e.what();
    }
  }
}

TEST(BatchMerge, NamesMissingRepeatedStoppedForeignAndCutOffRunsAndTheShardToRerun) {
  harness::TempDir dir;
  const BatchPlan plan = sixRunsInTwoShards();
  plan.write(dir.path());
  dir.write("runs-shard1of2.jsonl", linesOf({runOf(14, 6), runOf(10, 6), runOf(12, 5)}));
  dir.write("runs-shard2of2.jsonl",
            linesOf({runOf(11, 6), runOf(13, 2, true), runOf(11, 6), runOf(12, 6)}) +
                R"({"seed": 15, "placed")");

  const scenario::BatchCheck batch = scenario::checkBatch(dir.path());
  ASSERT_EQ(batch.shards.size(), 2u);
  EXPECT_TRUE(batch.shards[0].whole());
  const scenario::ShardCheck& second = batch.shards[1];
  EXPECT_EQ(second.missing, (std::vector<std::uint64_t>{13, 15}));  // 13 stopped, 15 cut off
  EXPECT_TRUE(mentions(second.problems, "line 3: seed 11 again (first on line 1)"));
  EXPECT_TRUE(mentions(second.problems, "line 4: seed 12 is not in shard 2/2"));
  EXPECT_TRUE(mentions(second.problems, "line 5: not JSON"));
  EXPECT_FALSE(batch.whole());
  EXPECT_EQ(batch.shardsToRerun(), std::vector<std::size_t>{2});

  // Shard 2 run again rewrites its file: the batch is whole, in seed order, totals exact.
  const std::vector<scenario::PegTransferResult> rerun{runOf(15, 6), runOf(13, 6), runOf(11, 6)};
  dir.write("runs-shard2of2.jsonl", linesOf(rerun));
  const scenario::BatchCheck whole = scenario::checkBatch(dir.path());
  EXPECT_TRUE(whole.whole());
  EXPECT_TRUE(whole.shardsToRerun().empty());
  std::vector<std::uint64_t> seeds;
  for (const auto& row : whole.rowsBySeed()) seeds.push_back(row["seed"].get<std::uint64_t>());
  EXPECT_EQ(seeds, (std::vector<std::uint64_t>{10, 11, 12, 13, 14, 15}));
  const nlohmann::json summary = whole.summary();
  const nlohmann::json expected = scenario::summarize(std::vector{
      runOf(10, 6), runOf(11, 6), runOf(12, 5), runOf(13, 6), runOf(14, 6), runOf(15, 6)});
  for (const char* key : {"runs", "runs_all_placed", "rings_placed", "steps", "sim_time_s",
                          "loop_time_s", "real_time_factor"}) {
    EXPECT_EQ(summary[key], expected[key]) << key;
  }
  EXPECT_EQ(summary["runs_all_placed"], 5);
  EXPECT_EQ(summary["options"], nlohmann::json(plan.options));
}

TEST(BatchMerge, AShardThatNeverRanIsMissingWholeWithNoFile) {
  harness::TempDir dir;
  sixRunsInTwoShards().write(dir.path());
  dir.write("runs-shard2of2.jsonl", linesOf({runOf(11, 6), runOf(13, 6), runOf(15, 6)}));
  const scenario::BatchCheck batch = scenario::checkBatch(dir.path());
  EXPECT_EQ(batch.shards[0].missing, (std::vector<std::uint64_t>{10, 12, 14}));
  EXPECT_TRUE(mentions(batch.shards[0].problems, "no results file"));
  EXPECT_EQ(batch.shardsToRerun(), std::vector<std::size_t>{1});
}

TEST(RunTiming, ReadsBackWhatItWrites) {
  const scenario::RunTiming timing{74.05, 11.4, 11.38, 74050};
  nlohmann::json j;
  timing.addTo(j);
  const auto back = scenario::RunTiming::fromJson(j);
  EXPECT_EQ(back.sim_time, timing.sim_time);
  EXPECT_EQ(back.wall_time, timing.wall_time);
  EXPECT_EQ(back.loop_seconds, timing.loop_seconds);
  EXPECT_EQ(back.steps, timing.steps);
}

}  // namespace
