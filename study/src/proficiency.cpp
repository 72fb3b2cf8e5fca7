#include "study/proficiency.hpp"

#include <algorithm>
#include <map>
#include <string>

namespace study {

namespace {

bool within(const TrialRecord& r) {
  const auto completed = r.metrics.find("completed");
  const auto time = r.metrics.find("completion_time_s");
  return completed != r.metrics.end() && completed->second > 0.5 && time != r.metrics.end() &&
         time->second <= *r.proficiency_time;
}

/// Whether a participant's trials of one task under one scheme, in repetition order, were
/// within the time twice in a row.
bool twiceInARow(std::vector<const TrialRecord*> trials) {
  std::sort(trials.begin(), trials.end(), [](const TrialRecord* a, const TrialRecord* b) {
    return a->repetition < b->repetition;
  });
  for (std::size_t i = 1; i < trials.size(); ++i) {
    if (within(*trials[i - 1]) && within(*trials[i])) return true;
  }
  return false;
}

}  // namespace

nlohmann::json proficiencySummary(const std::vector<TrialRecord>& trials) {
  // task -> scheme -> participant -> trials
  std::map<std::string,
           std::map<std::string, std::map<std::string, std::vector<const TrialRecord*>>>>
      grouped;
  std::map<std::string, double> bar;
  for (const TrialRecord& r : trials) {
    if (r.tuning || !r.proficiency_time) continue;
    grouped[r.task][r.condition][r.participant].push_back(&r);
    bar[r.task] = *r.proficiency_time;
  }
  nlohmann::json out = nlohmann::json::object();
  for (const auto& [task, schemes] : grouped) {
    out[task]["time_s"] = bar.at(task);
    for (const auto& [scheme, people] : schemes) {
      int count = 0, inside = 0, proficient = 0;
      for (const auto& [person, tried] : people) {
        count += static_cast<int>(tried.size());
        inside += static_cast<int>(
            std::count_if(tried.begin(), tried.end(), [](const auto* r) { return within(*r); }));
        proficient += twiceInARow(tried) ? 1 : 0;
      }
      out[task]["schemes"][scheme] = {{"trials", count},
                                      {"within", inside},
                                      {"participants", people.size()},
                                      {"proficient", proficient}};
    }
  }
  return out;
}

}  // namespace study
