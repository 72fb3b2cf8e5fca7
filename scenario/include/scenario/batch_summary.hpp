#pragma once
// The totals of a set of peg-transfer runs, as the summary JSON holds them.

#include <nlohmann/json.hpp>
#include <vector>

#include "scenario/peg_transfer_result.hpp"

namespace scenario {

/// Runs, runs with all six placed, pegs placed and lost, and the rates over all runs.
nlohmann::json summarize(const std::vector<PegTransferResult>& results);

}  // namespace scenario
