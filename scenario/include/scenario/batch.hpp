#pragma once
// Randomised batches of the peg transfer: which seeds a run set holds, how a shard `i/N` picks
// its share with no coordination (run k goes to shard k mod N), and running a share on worker
// threads. Every run is independent and seeded, so any split gives the same results.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "scenario/peg_transfer.hpp"

namespace scenario {

/// The most runs a batch may hold: a million peg transfers take some 200 CPU-days, and every
/// count beyond is a typo (a plan of 1e300 runs had its readers allocating until memory ran out).
inline constexpr std::size_t kMostRuns = 1'000'000;

/// Shard `index` of `count` (1-based, as `--shard 3/8` reads).
struct Shard {
  std::size_t index = 1;
  std::size_t count = 1;

  /// Parses "i/N" with 1 <= i <= N. Throws std::invalid_argument quoting the text otherwise.
  static Shard parse(std::string_view text);
  /// "i/N".
  std::string text() const;
  /// The JSON-lines file this shard's runs go to in `dir`: runs-shard3of8.jsonl (runs.jsonl
  /// for 1/1), so shards can share one folder.
  std::filesystem::path runsFile(const std::filesystem::path& dir) const;
  /// Its summary file in `dir`: summary-shard3of8.json (summary.json for 1/1).
  std::filesystem::path summaryFile(const std::filesystem::path& dir) const;

 private:
  std::string fileSuffix() const;
};

/// The seeds of runs first_seed .. first_seed + runs - 1 that fall to `shard`.
std::vector<std::uint64_t> seedsOf(std::uint64_t first_seed, std::size_t runs, const Shard& shard);

/// Runs `base` once per seed on `threads` worker threads (`base.progress`, if set, is called
/// from those threads); `on_result` is called, one call at a time in completion order, as each
/// run ends. Returns the results in seed order. A run that throws stops the batch and the
/// exception reaches the caller. When `base.stop` turns true no further run starts, the running
/// ones stop (`stopped`), and the runs that never started are left out of the results.
std::vector<PegTransferResult> runBatch(
    const PegTransferOptions& base, const std::vector<std::uint64_t>& seeds, std::size_t threads,
    const std::function<void(const PegTransferResult&)>& on_result = {});

}  // namespace scenario
