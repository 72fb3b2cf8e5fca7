#pragma once
// A batch split into shards for a scheduler, as `raven_batch plan` writes it to DIR/batch.json:
// which seeds, how many shards, and the options every shard's raven_peg_transfer gets. Array
// tasks, resubmissions and the merge all read it, so none of them repeats the batch's options.

#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "scenario/batch.hpp"

namespace scenario {

/// Seeds first_seed .. first_seed + runs - 1 in `shards` shards, each run with `options`.
struct BatchPlan {
  static constexpr const char* kFileName = "batch.json";

  std::uint64_t first_seed = 0;
  std::size_t runs = 1;
  std::size_t shards = 1;
  /// raven_peg_transfer's options for every run, e.g. {"--randomize", "--squeeze", "1.0"}.
  std::vector<std::string> options;

  /// Refuses (std::invalid_argument naming it) an option the plan itself sets (--seed, --runs,
  /// --shard, --out, --jsonl), one a batch cannot take (--task, --gui, --snapshot), more shards
  /// than runs, or no runs.
  void validate() const;
  Shard shard(std::size_t index) const { return {index, shards}; }
  /// raven_peg_transfer's arguments for shard `index` (1-based) writing into `dir`.
  std::vector<std::string> shardArguments(std::size_t index,
                                          const std::filesystem::path& dir) const;

  nlohmann::json json() const;
  /// Reads `dir`/batch.json; std::runtime_error naming the file and the field when it is
  /// missing, malformed or fails validate().
  static BatchPlan read(const std::filesystem::path& dir);
  /// Writes `dir`/batch.json. A folder holding another batch's plan is refused (so two batches
  /// never mix their shards' files); the same plan again is fine (a resubmission).
  void write(const std::filesystem::path& dir) const;

  bool operator==(const BatchPlan&) const = default;
};

}  // namespace scenario
