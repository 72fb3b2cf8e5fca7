#include "study/questionnaire.hpp"

#include <fmt/format.h>

#include <array>
#include <istream>
#include <ostream>
#include <stdexcept>

namespace study {

namespace {

constexpr std::array<const char*, 6> kTlxScales{
    "Mental demand: how mentally demanding was the task?",
    "Physical demand: how physically demanding was the task?",
    "Temporal demand: how hurried or rushed was the pace of the task?",
    "Performance: how successful were you in doing what you were asked? (0 perfect, 100 "
    "failure)",
    "Effort: how hard did you have to work to reach your level of performance?",
    "Frustration: how insecure, discouraged, irritated, stressed or annoyed were you?"};

constexpr std::array<const char*, 10> kSusItems{
    "I think that I would like to use this system frequently.",
    "I found the system unnecessarily complex.",
    "I thought the system was easy to use.",
    "I think that I would need the support of a technical person to be able to use this system.",
    "I found the various functions in this system were well integrated.",
    "I thought there was too much inconsistency in this system.",
    "I would imagine that most people would learn to use this system very quickly.",
    "I found the system very cumbersome to use.",
    "I felt very confident using the system.",
    "I needed to learn a lot of things before I could get going with this system."};

bool tlxValid(int a) {
  return a >= 0 && a <= 100 && a % 5 == 0;
}
bool susValid(int a) {
  return a >= 1 && a <= 5;
}

}  // namespace

nlohmann::json QuestionnaireAnswers::json() const {
  return {{"name", name}, {"answers", answers}, {"score", score}};
}

QuestionnaireAnswers QuestionnaireAnswers::fromJson(const nlohmann::json& j) {
  return {j.at("name").get<std::string>(), j.at("answers").get<std::vector<int>>(),
          j.at("score").get<double>()};
}

double rawTlx(const std::vector<int>& answers) {
  if (answers.size() != kTlxScales.size()) {
    throw std::invalid_argument("the NASA-TLX has six scales");
  }
  double sum = 0.0;
  for (int a : answers) {
    if (!tlxValid(a)) throw std::invalid_argument("a TLX answer is 0..100 in steps of 5");
    sum += a;
  }
  return sum / 6.0;
}

double susScore(const std::vector<int>& answers) {
  if (answers.size() != kSusItems.size()) throw std::invalid_argument("the SUS has ten items");
  int sum = 0;
  for (std::size_t i = 0; i < answers.size(); ++i) {
    if (!susValid(answers[i])) throw std::invalid_argument("a SUS answer is 1..5");
    sum += i % 2 == 0 ? answers[i] - 1 : 5 - answers[i];
  }
  return 2.5 * sum;
}

std::optional<QuestionnaireAnswers> ask(const std::string& name, const std::string& condition,
                                        std::istream& in, std::ostream& out) {
  const bool tlx = name == "nasa-tlx";
  if (!tlx && name != "sus") throw std::invalid_argument("unknown questionnaire " + name);
  QuestionnaireAnswers result{name, {}, 0.0};
  out << fmt::format("\n{} for condition {}: ", tlx ? "NASA-TLX" : "System Usability Scale",
                     condition)
      << (tlx ? "rate each from 0 (very low) to 100 (very high) in steps of 5.\n"
              : "1 strongly disagree .. 5 strongly agree.\n");
  const std::size_t count = tlx ? kTlxScales.size() : kSusItems.size();
  for (std::size_t i = 0; i < count; ++i) {
    for (;;) {
      out << fmt::format("  {}/{} {} > ", i + 1, count, tlx ? kTlxScales[i] : kSusItems[i])
          << std::flush;
      std::string line;
      if (!std::getline(in, line)) return std::nullopt;
      try {
        std::size_t used = 0;
        const int a = std::stoi(line, &used);
        if (line.find_first_not_of(" \t\r", used) == std::string::npos &&
            (tlx ? tlxValid(a) : susValid(a))) {
          result.answers.push_back(a);
          break;
        }
      } catch (const std::exception&) {
      }
      out << (tlx ? "  please answer 0..100 in steps of 5\n" : "  please answer 1..5\n");
    }
  }
  result.score = tlx ? rawTlx(result.answers) : susScore(result.answers);
  out << fmt::format("  score {:.1f}\n", result.score);
  return result;
}

}  // namespace study
