#pragma once
// The study's report from its sessions' sealed trials and questionnaires: per scheme the
// metrics' means and SDs, paired comparisons between schemes per task and metric (paired t-test
// with Cohen's d_z, the exact Wilcoxon signed-rank test beside it, Holm-corrected within each
// task's metric), the questionnaires' scores compared the same way, each tuned participant's
// recommended settings, and the participants a study needs (power of the paired t-test).
// summary.json, trials.csv (and trial_metrics_long.csv, one row per trial and metric) and
// questionnaires.csv hold the numbers; report.html draws them.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "study/questionnaire.hpp"
#include "study/trial_metrics.hpp"

namespace study {

/// One sealed trial as the report reads it (its trial.json).
struct TrialRecord {
  std::string participant;
  bool is_virtual = false;
  int index = 0;
  std::string condition, task;
  int repetition = 0;
  bool tuning = false;
  int trials_before = 0;
  TrialMetrics metrics;
  nlohmann::json tuning_record;            ///< settings, cost, parameters (tuning trials)
  std::optional<double> proficiency_time;  ///< s, the task's, when the protocol stated one
};

/// One questionnaire a participant answered after a condition.
struct AnsweredQuestionnaire {
  std::string participant, condition;
  QuestionnaireAnswers answers;
};

/// Everything the report reads.
struct StudyData {
  std::string study;
  std::vector<std::string> participants;
  std::vector<TrialRecord> trials;
  std::vector<AnsweredQuestionnaire> questionnaires;
};

/// Reads study folders (or single participants' folders). Throws std::runtime_error naming a
/// file that cannot be read; a folder with no session in it is an error too.
StudyData loadStudy(const std::vector<std::filesystem::path>& dirs);

/// How the power section is asked for.
struct PowerQuestion {
  double alpha = 0.05;
  double power = 0.8;
  std::vector<double> effects{0.5, 0.8, 1.2};  ///< stated d_z values
};

/// summary.json's content.
nlohmann::json summarize(const StudyData& data, const PowerQuestion& power = {});

/// Writes summary.json, trials.csv, trial_metrics_long.csv and questionnaires.csv into `out`,
/// then report.html (drawn by report/draw_study.py with matplotlib). Returns the empty string,
/// or why the drawing failed (the numbers are written either way).
std::string writeReport(const StudyData& data, const std::filesystem::path& out,
                        const PowerQuestion& power = {});

}  // namespace study
