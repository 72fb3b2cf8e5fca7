#include "study/study_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <set>

#include "study/participant_session.hpp"
#include "study/proficiency.hpp"
#include "study/settings_tuner.hpp"
#include "study/statistics.hpp"

namespace study {

namespace fs = std::filesystem;

namespace {

constexpr const char* kCorrection =
    "holm: within each task's metric (and each questionnaire), over the pairwise comparisons of "
    "the schemes";

void loadParticipant(const fs::path& home, StudyData& data) {
  const nlohmann::json session = readJson(home / "session.json");
  const std::string participant = session.at("participant").get<std::string>();
  const bool is_virtual = !session.at("virtual").is_null();
  if (data.study.empty()) data.study = session.at("study").get<std::string>();
  data.participants.push_back(participant);
  if (fs::is_directory(home / "trials")) {
    for (const auto& entry : fs::directory_iterator(home / "trials")) {
      const fs::path file = entry.path() / "trial.json";
      if (!fs::exists(file)) continue;  // cut short: not a trial
      const nlohmann::json j = readJson(file);
      TrialRecord r;
      r.participant = participant;
      r.is_virtual = is_virtual;
      const nlohmann::json& planned = j.at("planned");
      r.index = planned.at("index").get<int>();
      r.condition = planned.at("condition").get<std::string>();
      r.task = planned.at("task").get<std::string>();
      r.repetition = planned.at("repetition").get<int>();
      r.tuning = planned.at("tuning").get<bool>();
      r.trials_before = j.at("trials_before").get<int>();
      for (const auto& [name, v] : j.at("metrics").items()) {
        r.metrics[name] = v.is_null() ? std::nan("") : v.get<double>();
      }
      for (const std::string& m : metricNames()) {
        r.metrics.try_emplace(m, std::nan(""));  // measured before the metric existed
      }
      if (j.contains("tuning")) r.tuning_record = j.at("tuning");
      if (j.contains("proficiency_time_s")) {
        r.proficiency_time = j.at("proficiency_time_s").get<double>();
      }
      data.trials.push_back(r);
    }
  }
  if (fs::is_directory(home / "questionnaires")) {
    for (const auto& entry : fs::directory_iterator(home / "questionnaires")) {
      const nlohmann::json j = readJson(entry.path());
      data.questionnaires.push_back(
          {participant, j.at("condition").get<std::string>(), QuestionnaireAnswers::fromJson(j)});
    }
  }
}

/// Per participant, the mean of one measure over their rows under one condition.
using ParticipantMeans = std::map<std::string, double>;

nlohmann::json nullable(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nullptr;
}

/// Paired comparisons of every pair of conditions on one measure of one task (none: a
/// questionnaire, asked per condition), Holm-corrected together.
nlohmann::json compare(const std::string& measure, const std::optional<std::string>& task,
                       int sense, const std::map<std::string, ParticipantMeans>& by_condition,
                       const PowerQuestion& power, nlohmann::json& power_rows) {
  std::vector<std::string> conditions;
  for (const auto& [c, _] : by_condition) conditions.push_back(c);
  nlohmann::json rows = nlohmann::json::array();
  std::vector<double> raw;
  const int pairs = static_cast<int>(conditions.size() * (conditions.size() - 1) / 2);
  for (std::size_t i = 0; i < conditions.size(); ++i) {
    for (std::size_t k = i + 1; k < conditions.size(); ++k) {
      const auto& a = by_condition.at(conditions[i]);
      const auto& b = by_condition.at(conditions[k]);
      std::vector<double> xa, xb;
      for (const auto& [participant, va] : a) {
        const auto it = b.find(participant);
        if (it == b.end()) continue;
        if (!std::isfinite(va) || !std::isfinite(it->second)) continue;
        xa.push_back(va);
        xb.push_back(it->second);
      }
      if (xa.size() < 2) continue;
      const PairedT t = pairedT(xa, xb);
      const SignedRank w = wilcoxonSignedRank(xa, xb);
      const double difference = mean(xa) - mean(xb);
      std::string better;
      if (sense != 0 && t.p < 1.0 && difference != 0.0) {
        better = (difference < 0.0) == (sense < 0) ? conditions[i] : conditions[k];
      }
      const nlohmann::json of_task = task ? nlohmann::json(*task) : nlohmann::json(nullptr);
      rows.push_back(nlohmann::json{
          {"a", conditions[i]},
          {"b", conditions[k]},
          {"metric", measure},
          {"task", of_task},
          {"test", "paired t-test on the participants' means"},
          {"n", xa.size()},
          {"mean_a", mean(xa)},
          {"mean_b", mean(xb)},
          {"mean_difference", difference},
          {"t", nullable(t.t)},
          {"df", t.df},
          {"p_raw", t.p},
          {"effect_size", nullable(t.dz)},
          {"effect_size_is", "cohen_dz"},
          {"wilcoxon_p", w.p},
          {"wilcoxon_exact", w.exact},
          {"rank_biserial", w.rank_biserial},
          {"better", better.empty() ? nlohmann::json(nullptr) : nlohmann::json(better)}});
      raw.push_back(t.p);
      const double alpha = power.alpha / std::max(pairs, 1);
      power_rows.push_back({{"a", conditions[i]},
                            {"b", conditions[k]},
                            {"metric", measure},
                            {"task", of_task},
                            {"observed_effect", nullable(t.dz)},
                            {"participants_needed",
                             std::isfinite(t.dz) ? pairsNeeded(t.dz, alpha, power.power) : 2}});
    }
  }
  const std::vector<double> adjusted = holm(raw);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    rows[i]["p"] = adjusted[i];
    rows[i]["significant"] = adjusted[i] < 0.05;
  }
  return rows;
}

nlohmann::json describe(const std::vector<double>& values) {
  std::vector<double> finite;
  for (double v : values) {
    if (std::isfinite(v)) finite.push_back(v);
  }
  return {{"mean", nullable(mean(finite))}, {"sd", nullable(sd(finite))}, {"n", finite.size()}};
}

void writeCsv(const StudyData& data, const fs::path& out) {
  std::ofstream trials(out / "trials.csv");
  trials << "participant,virtual,index,condition,task,repetition,tuning,trials_before";
  for (const std::string& m : metricNames()) trials << ',' << m;
  trials << ",tuning_cost\n";
  for (const TrialRecord& r : data.trials) {
    trials << fmt::format("{},{},{},{},{},{},{},{}", r.participant, r.is_virtual ? 1 : 0, r.index,
                          r.condition, r.task, r.repetition, r.tuning ? 1 : 0, r.trials_before);
    for (const std::string& m : metricNames()) {
      const auto it = r.metrics.find(m);
      trials << ','
             << (it != r.metrics.end() && std::isfinite(it->second)
                     ? fmt::format("{:.6g}", it->second)
                     : "");
    }
    trials << ','
           << (r.tuning_record.contains("cost")
                   ? fmt::format("{:.6g}", r.tuning_record.at("cost").get<double>())
                   : "")
           << '\n';
  }
  // The same trials in long form, one row per trial and metric (R's tidy data, pandas' melt):
  // a metric that does not apply to a trial has no row.
  std::ofstream tidy(out / "trial_metrics_long.csv");
  tidy << "participant,virtual,condition,task,repetition,tuning,trials_before,metric,value\n";
  for (const TrialRecord& r : data.trials) {
    for (const auto& [metric, value] : r.metrics) {
      if (!std::isfinite(value)) continue;
      tidy << fmt::format("{},{},{},{},{},{},{},{},{:.6g}\n", r.participant, r.is_virtual ? 1 : 0,
                          r.condition, r.task, r.repetition, r.tuning ? 1 : 0, r.trials_before,
                          metric, value);
    }
  }
  std::ofstream answers(out / "questionnaires.csv");
  answers << "participant,condition,questionnaire,score,answers,weights\n";
  for (const AnsweredQuestionnaire& q : data.questionnaires) {
    answers << fmt::format("{},{},{},{:.2f},{},{}\n", q.participant, q.condition, q.answers.name,
                           q.answers.score, fmt::join(q.answers.answers, " "),
                           fmt::join(q.answers.weights, " "));
  }
  if (!trials || !tidy || !answers)
    throw std::runtime_error("cannot write the CSV files in " + out.string());
}

}  // namespace

StudyData loadStudy(const std::vector<fs::path>& dirs) {
  StudyData data;
  for (const fs::path& dir : dirs) {
    if (fs::exists(dir / "session.json")) {
      loadParticipant(dir, data);
      continue;
    }
    if (!fs::is_directory(dir)) throw std::runtime_error(dir.string() + ": no such folder");
    std::vector<fs::path> homes;
    for (const auto& entry : fs::directory_iterator(dir)) {
      if (fs::exists(entry.path() / "session.json")) homes.push_back(entry.path());
    }
    std::sort(homes.begin(), homes.end());
    if (homes.empty()) {
      throw std::runtime_error(dir.string() + ": no participant's session.json in it");
    }
    for (const fs::path& home : homes) loadParticipant(home, data);
  }
  std::sort(data.trials.begin(), data.trials.end(), [](const auto& a, const auto& b) {
    return std::tie(a.participant, a.index) < std::tie(b.participant, b.index);
  });
  return data;
}

namespace {

/// The comparison blocks' trials (not the tuning's), per scheme.
using TrialsByScheme = std::map<std::string, std::vector<const TrialRecord*>>;

/// Each metric's meaning and which way is better.
nlohmann::json metricDefinitions() {
  nlohmann::json metrics = nlohmann::json::object();
  for (const std::string& m : metricNames()) {
    metrics[m] = {{"meaning", metricMeaning(m)},
                  {"better", metricSense(m) < 0   ? "lower"
                             : metricSense(m) > 0 ? "higher"
                                                  : "neither"}};
  }
  return metrics;
}

/// Per scheme: its trials, participants and each metric described, over all and per task.
nlohmann::json describeSchemes(const TrialsByScheme& by_condition) {
  nlohmann::json schemes = nlohmann::json::object();
  for (const auto& [condition, rows] : by_condition) {
    nlohmann::json scheme{{"trials", rows.size()}};
    std::set<std::string> people, tasks;
    for (const TrialRecord* r : rows) {
      people.insert(r->participant);
      tasks.insert(r->task);
    }
    scheme["participants"] = people.size();
    for (const std::string& m : metricNames()) {
      std::vector<double> values;
      for (const TrialRecord* r : rows) values.push_back(r->metrics.at(m));
      scheme[m] = describe(values);
      for (const std::string& task : tasks) {
        std::vector<double> of_task;
        for (const TrialRecord* r : rows) {
          if (r->task == task) of_task.push_back(r->metrics.at(m));
        }
        scheme["tasks"][task][m] = describe(of_task);
      }
    }
    schemes[condition] = scheme;
  }
  return schemes;
}

/// Paired comparisons of the schemes, per task and metric, on the participants' means over
/// that task's trials (tasks differ in scale: a peg transfer's minutes would swamp a reach's
/// seconds), appended to `comparisons` (and the observed power to `power_rows`).
void compareMetrics(const TrialsByScheme& by_condition, const PowerQuestion& power,
                    nlohmann::json& comparisons, nlohmann::json& power_rows) {
  std::set<std::string> tasks;
  for (const auto& [condition, rows] : by_condition) {
    for (const TrialRecord* r : rows) tasks.insert(r->task);
  }
  for (const std::string& task : tasks) {
    for (const std::string& m : metricNames()) {
      std::map<std::string, ParticipantMeans> means;
      for (const auto& [condition, rows] : by_condition) {
        std::map<std::string, std::vector<double>> values;
        for (const TrialRecord* r : rows) {
          const double v = r->metrics.at(m);
          if (r->task == task && std::isfinite(v)) values[r->participant].push_back(v);
        }
        for (const auto& [participant, v] : values) means[condition][participant] = mean(v);
      }
      if (means.size() < 2) continue;
      for (auto& row : compare(m, task, metricSense(m), means, power, power_rows)) {
        comparisons.push_back(row);
      }
    }
  }
}

/// Which way a questionnaire's score is better: the TLXs' workload lower, the SUS higher; a
/// protocol's own Likert set says neither (its statements may point either way).
int questionnaireSense(const std::string& name) {
  if (name == "nasa-tlx" || name == "surg-tlx") return -1;
  return name == "sus" ? +1 : 0;
}

/// The questionnaires' scores per scheme, compared as the metrics are (appended to
/// `comparisons`).
nlohmann::json compareQuestionnaires(const StudyData& data, const PowerQuestion& power,
                                     nlohmann::json& comparisons, nlohmann::json& power_rows) {
  nlohmann::json questionnaires = nlohmann::json::object();
  std::set<std::string> names;
  for (const AnsweredQuestionnaire& q : data.questionnaires) names.insert(q.answers.name);
  for (const std::string& name : names) {
    std::map<std::string, ParticipantMeans> means;
    std::map<std::string, std::vector<double>> scores;
    for (const AnsweredQuestionnaire& q : data.questionnaires) {
      if (q.answers.name != name) continue;
      means[q.condition][q.participant] = q.answers.score;
      scores[q.condition].push_back(q.answers.score);
    }
    for (const auto& [condition, s] : scores) questionnaires[name][condition] = describe(s);
    if (means.size() < 2) continue;
    for (auto& row :
         compare(name, std::nullopt, questionnaireSense(name), means, power, power_rows)) {
      comparisons.push_back(row);
    }
  }
  return questionnaires;
}

/// Tuning: per participant, the settings the process predicts cheapest.
nlohmann::json recommendSettings(const StudyData& data) {
  nlohmann::json recommended = nlohmann::json::object();
  TrialsByScheme tuned;  // here: per participant
  for (const TrialRecord& r : data.trials) {
    if (r.tuning && !r.tuning_record.is_null()) tuned[r.participant].push_back(&r);
  }
  for (const auto& [participant, rows] : tuned) {
    std::vector<TunedParameter> parameters;
    for (const auto& p : rows.front()->tuning_record.at("parameters")) {
      parameters.push_back(
          {p.at("name").get<std::string>(), p.at("low").get<double>(), p.at("high").get<double>()});
    }
    std::vector<TuningObservation> history;
    for (const TrialRecord* r : rows) {
      history.push_back({r->tuning_record.at("settings").get<std::vector<double>>(),
                         r->tuning_record.at("cost").get<double>()});
    }
    const Recommendation best = SettingsTuner(parameters, 1).recommend(history);
    nlohmann::json settings;
    for (std::size_t i = 0; i < parameters.size(); ++i) {
      settings[parameters[i].name] = best.settings[i];
    }
    recommended[participant] = {
        {"settings", settings},
        {"predicted_cost", best.predicted_cost},
        {"cost", rows.front()->tuning_record.at("cost_is")},
        {"base_condition", rows.front()->condition},
        {"tuning_trials", rows.size()},
        {"method",
         "Gaussian-process Bayesian optimisation (expected improvement); the tried "
         "settings of lowest predicted cost"}};
  }
  return recommended;
}

/// The power analysis: what the comparisons observed, and the participants stated effects need.
nlohmann::json powerSection(const PowerQuestion& power, const nlohmann::json& power_rows) {
  nlohmann::json stated = nlohmann::json::array();
  for (double d : power.effects) {
    stated.push_back(
        {{"effect_size", d}, {"participants_needed", pairsNeeded(d, power.alpha, power.power)}});
  }
  return {{"test", "two-sided paired t-test (noncentral t)"},
          {"alpha", power.alpha},
          {"power", power.power},
          {"observed", power_rows},
          {"stated_effects", stated},
          {"note",
           "observed: the alpha is divided by the number of scheme pairs (Holm's "
           "strictest step); stated: for one comparison at alpha"}};
}

}  // namespace

nlohmann::json summarize(const StudyData& data, const PowerQuestion& power) {
  nlohmann::json j;
  j["study"] = data.study;
  j["participants"] = data.participants;
  j["virtual_participants"] =
      std::count_if(data.participants.begin(), data.participants.end(), [&](const auto& p) {
        return std::any_of(data.trials.begin(), data.trials.end(), [&](const TrialRecord& r) {
          return r.participant == p && r.is_virtual;
        });
      });
  j["trials"] = data.trials.size();
  j["correction"] = kCorrection;
  j["metrics"] = metricDefinitions();
  TrialsByScheme by_condition;
  for (const TrialRecord& r : data.trials) {
    if (!r.tuning) by_condition[r.condition].push_back(&r);
  }
  j["schemes"] = describeSchemes(by_condition);
  nlohmann::json comparisons = nlohmann::json::array();
  nlohmann::json power_rows = nlohmann::json::array();
  compareMetrics(by_condition, power, comparisons, power_rows);
  j["questionnaires"] = compareQuestionnaires(data, power, comparisons, power_rows);
  j["comparisons"] = comparisons;
  j["recommended"] = recommendSettings(data);
  j["proficiency"] = proficiencySummary(data.trials);
  j["power"] = powerSection(power, power_rows);
  return j;
}

std::string writeReport(const StudyData& data, const fs::path& out, const PowerQuestion& power) {
  fs::create_directories(out);
  writeJsonAtomically(out / "summary.json", summarize(data, power));
  writeCsv(data, out);
  const std::string command =
      fmt::format("/usr/bin/python3 '{}' '{}'", RAVEN_STUDY_DRAW_SCRIPT, out.string());
  const int status = std::system(command.c_str());
  if (status == 0) return "";
  return fmt::format("{} exited with status {} (is python3-matplotlib installed?)",
                     RAVEN_STUDY_DRAW_SCRIPT, status);
}

}  // namespace study
