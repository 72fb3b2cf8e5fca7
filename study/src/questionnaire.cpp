#include "study/questionnaire.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace study {

namespace {

/// The TLXs' 21 marks: 0 to 100 in fives.
AnswerScale workloadScale(const char* high = "very high") {
  return {.low = 0, .high = 100, .step = 5, .low_label = "very low", .high_label = high};
}

const char* const kPairwiseNote =
    " Then, for each pair of the scales, choose the one that contributed more to the workload of "
    "the task.";

QuestionnaireForm nasaTlx() {
  return {
      .name = "nasa-tlx",
      .title = "NASA Task Load Index",
      .instructions = "Rate each scale for the task you just did.",
      .items = {{"Mental demand", "How mentally demanding was the task?"},
                {"Physical demand", "How physically demanding was the task?"},
                {"Temporal demand", "How hurried or rushed was the pace of the task?"},
                {"Performance",
                 "How successful were you in doing what you were asked? (0 perfect, 100 failure)"},
                {"Effort", "How hard did you have to work to reach your level of performance?"},
                {"Frustration",
                 "How insecure, discouraged, irritated, stressed or annoyed were you?"}},
      .scale = workloadScale(),
  };
}

QuestionnaireForm surgTlx() {
  return {
      .name = "surg-tlx",
      .title = "Surgery Task Load Index (SURG-TLX)",
      .instructions = "Rate each demand of the task you just did.",
      .items = {{"Mental demands", "How mentally fatiguing was the task?"},
                {"Physical demands", "How physically fatiguing was the task?"},
                {"Temporal demands", "How hurried or rushed was the pace of the task?"},
                {"Task complexity", "How complex was the task?"},
                {"Situational stress", "How anxious did you feel while doing the task?"},
                {"Distractions", "How distracting was the place you worked in?"}},
      .scale = workloadScale(),
  };
}

QuestionnaireForm sus() {
  const std::vector<std::string> statements{
      "I think that I would like to use this system frequently.",
      "I found the system unnecessarily complex.",
      "I thought the system was easy to use.",
      "I think that I would need the support of a technical person to be able to use this "
      "system.",
      "I found the various functions in this system were well integrated.",
      "I thought there was too much inconsistency in this system.",
      "I would imagine that most people would learn to use this system very quickly.",
      "I found the system very cumbersome to use.",
      "I felt very confident using the system.",
      "I needed to learn a lot of things before I could get going with this system."};
  QuestionnaireForm form = likertForm("sus", statements, 5);
  form.title = "System Usability Scale";
  form.scoring = Scoring::Sus;
  return form;
}

}  // namespace

std::optional<int> wholeNumber(const std::string& text) {
  try {
    std::size_t used = 0;
    const int v = std::stoi(text, &used);
    if (text.find_first_not_of(" \t\r\n", used) == std::string::npos) return v;
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

bool AnswerScale::valid(int answer) const {
  return answer >= low && answer <= high && (answer - low) % step == 0;
}

std::string AnswerScale::rule() const {
  return step == 1 ? fmt::format("{}..{}", low, high)
                   : fmt::format("{}..{} in steps of {}", low, high, step);
}

std::vector<std::pair<int, int>> QuestionnaireForm::pairs() const {
  std::vector<std::pair<int, int>> out;
  if (!pairwise_weights) return out;
  const int n = static_cast<int>(items.size());
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) out.emplace_back(i, j);
  }
  return out;
}

std::optional<QuestionnaireForm> builtinForm(const std::string& name, bool weighted) {
  std::optional<QuestionnaireForm> form;
  if (name == "nasa-tlx") form = nasaTlx();
  if (name == "surg-tlx") form = surgTlx();
  if (name == "sus") return sus();
  if (form && weighted) {
    form->pairwise_weights = true;
    form->instructions += kPairwiseNote;
  }
  return form;
}

QuestionnaireForm likertForm(const std::string& name, const std::vector<std::string>& statements,
                             int points) {
  QuestionnaireForm form{
      .name = name,
      .title = name,
      .instructions = "How much do you agree with each statement?",
      .items = {},
      .scale = {.low = 1,
                .high = points,
                .step = 1,
                .low_label = "strongly disagree",
                .high_label = "strongly agree"},
  };
  for (const std::string& s : statements) form.items.push_back({s, s});
  return form;
}

nlohmann::json QuestionnaireAnswers::json() const {
  nlohmann::json j{{"name", name}, {"answers", answers}, {"score", score}};
  if (!weights.empty()) j["weights"] = weights;
  return j;
}

QuestionnaireAnswers QuestionnaireAnswers::fromJson(const nlohmann::json& j) {
  return {j.at("name").get<std::string>(), j.at("answers").get<std::vector<int>>(),
          j.value("weights", std::vector<int>{}), j.at("score").get<double>()};
}

QuestionnaireAnswers scoreAnswers(const QuestionnaireForm& form, const std::vector<int>& answers,
                                  const std::vector<int>& choices) {
  if (answers.size() != form.items.size()) {
    throw std::invalid_argument(
        fmt::format("{} has {} items, not {}", form.name, form.items.size(), answers.size()));
  }
  for (std::size_t i = 0; i < answers.size(); ++i) {
    if (!form.scale.valid(answers[i])) {
      throw std::invalid_argument(fmt::format("{} item {} ({}): {} is not {}", form.name, i + 1,
                                              form.items[i].label, answers[i], form.scale.rule()));
    }
  }
  const auto pairs = form.pairs();
  if (choices.size() != pairs.size()) {
    throw std::invalid_argument(
        fmt::format("{} asks {} pairs, not {}", form.name, pairs.size(), choices.size()));
  }
  QuestionnaireAnswers result{form.name, answers, {}, 0.0};
  if (!pairs.empty()) result.weights.assign(answers.size(), 0);
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const auto [a, b] = pairs[k];
    if (choices[k] != a && choices[k] != b) {
      throw std::invalid_argument(fmt::format("{} pair {}: choose {} or {}", form.name, k + 1,
                                              form.items[a].label, form.items[b].label));
    }
    ++result.weights[choices[k]];
  }
  double sum = 0.0;
  for (std::size_t i = 0; i < answers.size(); ++i) {
    if (form.scoring == Scoring::Sus) {
      sum += i % 2 == 0 ? answers[i] - 1 : 5 - answers[i];
    } else {
      sum += answers[i] * (pairs.empty() ? 1.0 : result.weights[i]);
    }
  }
  const double count = pairs.empty() ? static_cast<double>(answers.size()) : pairs.size();
  result.score = form.scoring == Scoring::Sus ? 2.5 * sum : sum / count;
  return result;
}

}  // namespace study
