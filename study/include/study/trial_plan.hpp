#pragma once
// A participant's plan: the conditions in their counterbalanced order, each one's trials (every
// task, repeated), then the tuning block's trials. Fixed before the first trial, so a resumed
// session runs exactly what is left of it.

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "study/protocol.hpp"

namespace study {

/// One trial the plan holds.
struct PlannedTrial {
  int index = 0;          ///< position in the plan (0-based)
  std::string condition;  ///< a protocol condition (the tuning block's base condition)
  std::string task;
  int repetition = 0;   ///< within the condition (tuning: the tuning trial's number)
  bool tuning = false;  ///< its settings are proposed by the optimiser when it starts
  /// The task's own draw (random targets): the same for a repetition under every condition, so
  /// the conditions are compared on the same targets.
  std::uint64_t task_seed = 0;

  /// "003_M2_reach_1": the folder its files go to.
  std::string folderName() const;
  nlohmann::json json() const;
  static PlannedTrial fromJson(const nlohmann::json& j);
};

/// The plan for the participant at `position` (0-based arrival order).
std::vector<PlannedTrial> planTrials(const Protocol& protocol, int position);

/// The conditions in the order `position` takes them.
std::vector<std::string> conditionSequence(const Protocol& protocol, int position);

}  // namespace study
