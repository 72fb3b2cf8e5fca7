#pragma once
// The totals of a set of peg-transfer runs, as the summary JSON holds them.

#include <nlohmann/json.hpp>
#include <vector>

#include "scenario/peg_transfer_result.hpp"

namespace scenario {

/// Runs, runs with all six placed, rings placed and lost, re-grasps, runs timed out, and the
/// clocks summed with the rates over all runs, from each run's JSON row
/// (PegTransferResult::json), so a merge of shards' JSON lines totals exactly as one process.
nlohmann::json summarize(const std::vector<nlohmann::json>& rows);

/// The same totals from the results themselves.
nlohmann::json summarize(const std::vector<PegTransferResult>& results);

}  // namespace scenario
