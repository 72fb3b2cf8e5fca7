#pragma once
// The FLS-style proficiency line of a study's report: for each task whose protocol states a
// proficiency time, per scheme, how many trials finished within it and how many participants
// did so on two consecutive repetitions: the consecutive part of the proficiency rule of the
// FLS skills curriculum (Ritter & Scott 2007, Surg Innov 14:107: the level reached on two
// consecutive trials and ten more; a study's few repetitions rarely allow the ten).

#include <nlohmann/json.hpp>
#include <vector>

#include "study/study_report.hpp"

namespace study {

/// {task: {"time_s", "schemes": {scheme: {"trials", "within", "participants", "proficient"}}}}
/// over the compared (not tuning) trials of tasks with a proficiency time; empty when none has.
/// A trial is within when it was completed in at most the time.
nlohmann::json proficiencySummary(const std::vector<TrialRecord>& trials);

}  // namespace study
