#pragma once
// A program run to its end for what it prints: the sections that take their figures from a
// script's output (Python, the policy's retraining).

#include <optional>
#include <string>
#include <vector>

namespace bench {

/// Runs `argv` (stdout and stderr together) for at most `timeout` wall seconds; its output's
/// lines, or nothing if it failed or had to be killed.
std::optional<std::vector<std::string>> outputLinesOf(const std::vector<std::string>& argv,
                                                      double timeout);

}  // namespace bench
