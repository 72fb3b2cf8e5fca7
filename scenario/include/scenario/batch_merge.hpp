#pragma once
// Checking that a sharded batch came back whole and merging it: every seed of the plan exactly
// once, finished (not stopped), in its own shard's file, and the shards to run again otherwise.

#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "scenario/batch_plan.hpp"

namespace scenario {

/// What one shard's JSON-lines file holds against the seeds its share of the batch asks for.
struct ShardCheck {
  Shard shard;
  std::filesystem::path file;
  std::vector<nlohmann::json> rows;    ///< its finished runs, one per seed
  std::vector<std::uint64_t> missing;  ///< its seeds with no finished run
  std::vector<std::string> problems;   ///< what else is wrong ("line 3: seed 12 twice", ...)

  bool whole() const { return missing.empty() && problems.empty(); }
};

/// A batch folder, checked shard by shard against its plan.
struct BatchCheck {
  BatchPlan plan;
  std::vector<ShardCheck> shards;

  bool whole() const;
  /// The shards to run again (1-based): any with a seed missing or a problem. Running one
  /// rewrites its file, so resubmitting exactly these completes the batch.
  std::vector<std::size_t> shardsToRerun() const;
  /// Every finished run, in seed order.
  std::vector<nlohmann::json> rowsBySeed() const;
  /// The batch's summary (summarize's totals, the plan, every run), as one process writes it.
  nlohmann::json summary() const;
};

/// Reads `dir`'s plan (BatchPlan::read) and every shard's results file.
BatchCheck checkBatch(const std::filesystem::path& dir);

/// Checks one shard's file: each line a finished run of one of its seeds, each seed once.
ShardCheck checkShard(const BatchPlan& plan, std::size_t index, const std::filesystem::path& dir);

}  // namespace scenario
