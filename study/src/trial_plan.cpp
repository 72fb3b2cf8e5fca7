#include "study/trial_plan.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "study/counterbalance.hpp"

namespace study {

std::string PlannedTrial::folderName() const {
  return fmt::format("{:03d}_{}_{}_{}", index, tuning ? "tuning" : condition, task, repetition);
}

nlohmann::json PlannedTrial::json() const {
  return {{"index", index},           {"condition", condition}, {"task", task},
          {"repetition", repetition}, {"tuning", tuning},       {"task_seed", task_seed}};
}

PlannedTrial PlannedTrial::fromJson(const nlohmann::json& j) {
  PlannedTrial t;
  t.index = j.at("index").get<int>();
  t.condition = j.at("condition").get<std::string>();
  t.task = j.at("task").get<std::string>();
  t.repetition = j.at("repetition").get<int>();
  t.tuning = j.at("tuning").get<bool>();
  t.task_seed = j.at("task_seed").get<std::uint64_t>();
  return t;
}

std::vector<std::string> conditionSequence(const Protocol& protocol, int position) {
  const int n = static_cast<int>(protocol.conditions.size());
  std::vector<std::string> out;
  for (int i = 0; i < n; ++i) {
    const int c = protocol.order == OrderKind::LatinSquare
                      ? conditionOrder(n, position)[static_cast<std::size_t>(i)]
                      : i;
    out.push_back(protocol.conditions[static_cast<std::size_t>(c)].name);
  }
  return out;
}

std::vector<PlannedTrial> planTrials(const Protocol& protocol, int position) {
  const auto seedOf = [](const std::string& task, int repetition) {
    std::uint64_t h = 14695981039346656037ull;  // FNV-1a: the same on every machine
    for (const char c : fmt::format("{}#{}", task, repetition)) {
      h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ull;
    }
    return h;
  };
  const auto trialsOf = [&](const TaskSpec& task) {
    return task.trials.value_or(protocol.trials_per_condition);
  };
  int rounds = 0;
  for (const TaskSpec& task : protocol.tasks) rounds = std::max(rounds, trialsOf(task));
  std::vector<PlannedTrial> plan;
  for (const std::string& condition : conditionSequence(protocol, position)) {
    for (int round = 0; round < rounds; ++round) {
      for (const TaskSpec& task : protocol.tasks) {
        // A task done fewer times joins in the condition's last rounds.
        const int rep = round - (rounds - trialsOf(task));
        if (rep < 0) continue;
        plan.push_back({static_cast<int>(plan.size()), condition, task.name, rep, false,
                        seedOf(task.name, rep)});
      }
    }
  }
  if (const auto& t = protocol.tuning) {
    for (int k = 0; k < t->trials; ++k) {
      plan.push_back({static_cast<int>(plan.size()), t->condition, t->task, k, true,
                      seedOf(t->task, 1000 + k)});
    }
  }
  return plan;
}

}  // namespace study
