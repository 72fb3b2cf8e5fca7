#pragma once
// The totals of a set of peg-transfer runs, as the summary JSON holds them.

#include <nlohmann/json.hpp>
#include <vector>

#include "scenario/peg_transfer_result.hpp"

namespace scenario {

/// Runs, runs with all six placed, rings placed and lost, re-grasps, runs timed out, and the
/// clocks summed, added up one run's JSON row (PegTransferResult::json) at a time: a batch keeps
/// its totals in constant memory however many runs it has.
class RunTotals {
 public:
  void add(const nlohmann::json& row);
  /// The totals, with the rates over all runs added so far.
  nlohmann::json json() const;

 private:
  std::size_t runs_ = 0, complete_ = 0, placed_ = 0, lost_ = 0, timed_out_ = 0, failed_ = 0,
              regrasps_ = 0;
  RunTiming time_;
};

/// The totals of these rows (RunTotals), so a merge of shards' JSON lines totals exactly as one
/// process.
nlohmann::json summarize(const std::vector<nlohmann::json>& rows);

/// The same totals from the results themselves.
nlohmann::json summarize(const std::vector<PegTransferResult>& results);

}  // namespace scenario
